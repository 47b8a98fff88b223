// Mesh.MaxElements must be positive: refused at the assignment.
Mesh.MaxElements = 0;   // expect error: 2:20: invalid-option-value
// compare_with_gmsh: skip
