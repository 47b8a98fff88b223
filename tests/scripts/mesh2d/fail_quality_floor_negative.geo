Mesh.QualityFloor = -0.1;   // expect error: 1:21: invalid-option-value
// compare_with_gmsh: skip
