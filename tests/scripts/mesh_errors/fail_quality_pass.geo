Mesh.QualityPass = 2;   // expect error: 1:20: invalid-option-value
// compare_with_gmsh: skip
