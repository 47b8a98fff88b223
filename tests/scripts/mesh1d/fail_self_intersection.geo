// A coastline that crosses itself (a figure eight around 10 E, 40 N) as the hole of an
// ocean surface on a unit PolarSphere: the repair loop splits the crossing edges down to
// the tolerance and stops with the located error at the Mesh statement.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
For i In {0:39}
  s = 2 * Pi * i / 40;
  lon = (10 + 8 * Sin(s)) * Pi / 180;
  lat = (40 + 4 * Sin(2 * s)) * Pi / 180;
  x = Cos(lat) * Cos(lon); y = Cos(lat) * Sin(lon); z = Sin(lat);
  Point(10 + i) = {-x / (1 + z), -y / (1 + z), 0};
EndFor
BSpline(1) = {10:49, 10};
Point(100) = {-2, -2, 0};
Point(101) = {2, -2, 0};
Point(102) = {2, 2, 0};
Point(103) = {-2, 2, 0};
Line(2) = {100, 101};
Line(3) = {101, 102};
Line(4) = {102, 103};
Line(5) = {103, 100};
Curve Loop(1) = {2, 3, 4, 5};
Curve Loop(2) = {1};
Plane Surface(1) = {1, 2};
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeMax = 0.005;
Mesh 1;   // expect error: 28:1: curves-intersect
// compare_with_gmsh: skip
