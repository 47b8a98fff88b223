// Latitudes beyond the poles are refused where the box is set.
Mesh.PictureBox = {0, 10, -95, 30};   // expect error: 2:19: invalid-option-value: Mesh.PictureBox: latitudes south -95 and north 30 must lie in [-90, 90]
// compare_with_gmsh: skip (native option)
