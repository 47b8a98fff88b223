// A count read as an int gets a bound an int holds (and a run can finish).
Mesh.Smoothing = 1e300;   // expect error: 2:18: invalid-option-value
// compare_with_gmsh: skip
