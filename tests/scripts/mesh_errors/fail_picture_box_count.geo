// A box is four numbers {W, E, S, N}.
Mesh.PictureBox = {0, 10, 40};   // expect error: 2:19: invalid-option-value
// compare_with_gmsh: skip (native option)
