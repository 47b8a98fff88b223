// Mesh.NbPartitions below 0 is refused where it is set.
Mesh.NbPartitions = -1;   // expect error: 2:21: invalid-option-value
// compare_with_gmsh: skip
