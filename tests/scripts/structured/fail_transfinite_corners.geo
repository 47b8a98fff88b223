// A transfinite surface has 3 or 4 corners.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Transfinite Surface{1} = {1, 2};   // expect error: 6:26: invalid-operation
// compare_with_gmsh: skip
