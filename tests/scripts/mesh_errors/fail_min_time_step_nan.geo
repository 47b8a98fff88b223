// Mesh.MinTimeStep NaN (inf - inf): refused at the assignment, as every option takes finite numbers only.
x = 1e308 * 10;
Mesh.MinTimeStep = x - x;   // expect error: 3:20: invalid-option-value
// compare_with_gmsh: skip
