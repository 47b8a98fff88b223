// A Mesh.DepthField that cannot be built is reported at Mesh, before meshing (it used to
// be found only when the fort.14 was written, after the meshing was paid for).
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {0, 1, 0, 0.2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[2] = TimeStep;
Field[2].DepthField = 3;
Field[2].Dt = 0;
Field[3] = MathEval;
Field[3].F = "10";
Mesh.DepthField = 2;
Mesh 2;
// expect error: 13:1: bad-field-value
