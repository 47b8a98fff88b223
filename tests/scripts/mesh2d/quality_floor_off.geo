// Mesh.QualityFloor = 0 turns the floor off: the same 5-degree corner, no report.
Mesh.QualityFloor = 0;
a = 5 * Pi / 180;
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {Cos(a), Sin(a), 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1:3}; Plane Surface(1) = {1};
Mesh 2;
Printf("%g", Mesh.QualityFloor);   // expect: 0
// compare_with_gmsh: skip
