// Mesh.PictureWorst counts triangles: a whole number.
Mesh.PictureWorst = 2.5;   // expect error: 2:21: invalid-option-value
// compare_with_gmsh: skip (native option)
