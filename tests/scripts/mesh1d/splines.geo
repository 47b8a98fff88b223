// 1D node counts on Spline, BSpline (open and closed) and Bezier curves against gmsh
// 4.8.4 -1, with Mesh.MinimumCurveNodes on a curve coarser than its size.
For i In {0:9}
  Point(1 + i) = {i, Sin(i), 0, 0.05 + 0.02 * i};
EndFor
Spline(1) = {1:10};
For i In {0:7}
  Point(20 + i) = {i, 3 + Cos(i), 0, 0.1};
EndFor
BSpline(2) = {20:27};
Point(30) = {0, 6, 0, 0.08};
Point(31) = {2, 6, 0, 0.08};
Point(32) = {2, 8, 0, 0.08};
Point(33) = {0, 8, 0, 0.08};
BSpline(3) = {30, 31, 32, 33, 30};
Bezier(4) = {30, 31, 32};
Point(40) = {20, 0, 0, 1000};
Point(41) = {21, 1, 0, 1000};
Point(42) = {22, 0, 0, 1000};
Mesh.MinimumCurveNodes = 5;
Spline(5) = {40, 41, 42};
Mesh 1;
gmsh_nodes = 293;   // Mesh.NbNodes after gmsh 4.8.4 meshes this script (gmsh -1)
Printf("within 5 percent: %g", Fabs(Mesh.NbNodes - gmsh_nodes) <= 0.05 * gmsh_nodes);   // expect: within 5 percent: 1
Printf("%g nodes", Mesh.NbNodes);   // expect: 293 nodes
