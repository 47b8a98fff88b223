// Mesh.QualityFloor is a rho: 0 (off) to 0.9; above that no mesh could meet it.
Mesh.QualityFloor = 0.95;   // expect error: 2:21: invalid-option-value
// compare_with_gmsh: skip
