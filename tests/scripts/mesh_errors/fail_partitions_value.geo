// Mesh.NbPartitions is a whole number of parts (0: none): 2.5 or -1 is refused where it is set.
Mesh.NbPartitions = 2.5;   // expect error: 2:21: invalid-option-value
// compare_with_gmsh: skip
