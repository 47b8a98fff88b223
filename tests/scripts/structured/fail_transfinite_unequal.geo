// Opposite sides of a transfinite surface with different node counts: Gmsh's error.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1} = 5;
Transfinite Curve{2, 3, 4} = 4;
Transfinite Surface{1};
Mesh 2;   // expect error: 9:1: mesh-error: surface 1: cannot be meshed using the transfinite algo (divisions 3 != 4 or 3 != 3)
