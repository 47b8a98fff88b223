// A background field whose sizes turn negative inside the square: meshing stops at the
// first bad size, reported at the field's definition (the Background Field statement
// comes as a note), and no mesh is made.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = MathEval;
Field[1].F = "0.1 * (x - 0.5)";
Background Field = 1;
Mesh 2;
// expect error: 14:1: bad-field-value: Field[1] (MathEval) gives the mesh size -0.05 at (0, 0, 0): a size must be finite and positive
