// Surface 1 has an embedded point that surface 2 lacks (Gmsh: "Different number of points
// (5 vs 4) for periodic correspondance"): a copy would need the point's image, so the
// statement is refused.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0}; Point(6) = {3, 0, 0}; Point(7) = {3, 1, 0}; Point(8) = {2, 1, 0};
Point(9) = {0.5, 0.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Point{9} In Surface{1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Periodic Surface 2 {5, 6, 7, 8} = 1 {1, 2, 3, 4};
// expect error: 11:1: invalid-operation
