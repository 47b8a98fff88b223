// A curve loop whose curves do not chain: Gmsh 4.8.4 creates it unchecked (we warn), and
// the surface bounded by it is the error, which names the curve where the chain breaks
// (a note points at the statement that created it).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
// expect warning: 12:1: gmsh-compat
// expect error: 13:1: loop-not-closed
