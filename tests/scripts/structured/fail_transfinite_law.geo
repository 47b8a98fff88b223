// An unknown law is refused where it is written.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Transfinite Curve{1} = 5 Using Geometric 1.2;   // expect error: 4:1: invalid-operation
// compare_with_gmsh: skip
