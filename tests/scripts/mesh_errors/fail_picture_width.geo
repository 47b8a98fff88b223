// Option values are checked where the script sets them, not when the picture is written.
Mesh.PictureWidth = 1e6;   // expect error: 2:21: invalid-option-value
// compare_with_gmsh: skip
