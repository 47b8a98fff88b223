// Mesh.MinTimeStep without Mesh.DepthField: no step can be computed, refused at the Mesh
// statement (the depth field may be defined after the option), the assignment as a note.
Mesh.MinTimeStep = 10;
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 2;   // expect error: 8:1: invalid-option-value
// compare_with_gmsh: skip
