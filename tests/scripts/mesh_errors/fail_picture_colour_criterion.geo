// Colouring by the size criterion needs a size field: without one, the Save that asked
// for the picture fails (nothing is written) and says what is missing.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh.PictureColour = 3;
Mesh 2;
Save "/tmp/stereomesh_fail_picture_colour_criterion.svg";   // expect error: 9:6: file-write-error
// compare_with_gmsh: skip (native option)
