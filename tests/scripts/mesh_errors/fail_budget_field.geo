// A size field of 1e-7 on a unit square asks for about 2e14 triangles: refused before
// the 4e7 boundary nodes are placed (the faces' budgets on a coarse boundary), at the
// Mesh statement, with the surface's statement as a note.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = MathEval;
Field[1].F = "1e-7";
Background Field = 1;
Mesh 2;   // expect error: 11:1: limit-exceeded
// compare_with_gmsh: skip
