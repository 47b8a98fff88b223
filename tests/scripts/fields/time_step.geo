// TimeStep: Dt sqrt(9.81 H) / Courant, H from DepthField raised to MinDepth (default 10).
Field[1] = MathEval;
Field[1].F = "x";
Field[2] = TimeStep;
Field[2].DepthField = 1;
Field[2].Dt = 10;
Printf("%.6g", FieldValue(2, 1000, 0, 0));    // expect: 990.454
Printf("%.6g", FieldValue(2, 1, 0, 0));       // expect: 99.0454
Field[2].MinDepth = 0.5;
Printf("%.6g", FieldValue(2, 1, 0, 0));       // expect: 31.3209
Field[2].Courant = 0.5;
Printf("%.6g", FieldValue(2, 1000, 0, 0));    // expect: 1980.91
// The summary's time step of a mesh with a depth field (Mesh.StatsTimeStep): a right
// triangle of legs 100 m at 9.81 m depth, meshed at 200 m (one triangle): dt = shortest edge / 9.81.
Point(1) = {0, 0, 0, 200};
Point(2) = {100, 0, 0, 200};
Point(3) = {0, 100, 0, 200};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[3] = MathEval;
Field[3].F = "9.81";
Mesh.DepthField = 3;
Mesh 2;
Printf("%g triangle, dt %.6g s", Mesh.NbTriangles, Mesh.StatsTimeStep);   // expect: 1 triangle, dt 10.1937 s
