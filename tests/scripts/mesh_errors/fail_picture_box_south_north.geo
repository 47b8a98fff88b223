// A box whose south is not below its north frames nothing: refused where it is set.
Mesh.PictureBox = {-6, -5, 36.5, 35.5};   // expect error: 2:19: invalid-option-value: Mesh.PictureBox: south 36.5 must be below north 35.5 (the box is {W, E, S, N})
// compare_with_gmsh: skip (native option)
