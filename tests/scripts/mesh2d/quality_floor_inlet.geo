// A square with an inlet 0.01 wide, meshed at one size (0.115) that does not see how
// narrow it is: the triangles at its end start near rho 0.16; the floor lifts them.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0.505, 1, 0};
Point(5) = {0.505, 0.6, 0}; Point(6) = {0.495, 0.6, 0}; Point(7) = {0.495, 1, 0}; Point(8) = {0, 1, 0};
For i In {1:8} Line(i) = {i, (i % 8) + 1}; EndFor
Curve Loop(1) = {1:8}; Plane Surface(1) = {1};
Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeMax = 0.115;
Mesh.QualityFloor = 0;
Mesh 2;
Printf("%d", Mesh.StatsRhoMin < 0.3);   // expect: 1
Mesh.QualityFloor = 0.3;
Mesh 2;
Printf("%d", Mesh.StatsRhoMin >= 0.3);   // expect: 1
// compare_with_gmsh: skip
