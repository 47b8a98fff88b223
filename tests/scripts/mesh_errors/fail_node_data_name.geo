// Mesh.NodeData names depth, size and criterion only: another word is refused where the
// option is set, not when the file is written.
Mesh.NodeData = "depth, slope";   // expect error: 3:17: invalid-option-value: Mesh.NodeData: unknown value 'slope' (use depth, size or criterion, comma-separated)
// compare_with_gmsh: skip (native option)
