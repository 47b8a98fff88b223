// 1D meshing on a unit PolarSphere with a background size field (the paper's setting,
// section 3.2): closed BSplines drawn in (u,v), sizes from a MathEval field evaluated at
// the 3D points, point sizes off; node count against gmsh 4.8.4 -1.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
// An island outline: lon/lat in degrees -> PolarSphere (u,v) = -(x, y) / (1 + z).
Macro Island
  first = newp;
  For i In {0:n - 1}
    a = 2 * Pi * i / n;
    lon = (lon0 + rx * Cos(a) * (1 + 0.15 * Sin(5 * a))) * Pi / 180;
    lat = (lat0 + ry * Sin(a)) * Pi / 180;
    x = Cos(lat) * Cos(lon); y = Cos(lat) * Sin(lon); z = Sin(lat);
    Point(first + i) = {-x / (1 + z), -y / (1 + z), 0};
  EndFor
  c = newc;
  BSpline(c) = {first : first + n - 1, first};
Return
lon0 = 10; lat0 = 40; rx = 20; ry = 10; n = 60; Call Island;
lon0 = -60; lat0 = -20; rx = 8; ry = 15; n = 40; Call Island;
lon0 = 120; lat0 = 10; rx = 30; ry = 5; n = 80; Call Island;
Field[1] = MathEval;
Field[1].F = "0.01 + 0.03 * (z + 1)";
Background Field = 1;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh 1;
gmsh_nodes = 302;   // Mesh.NbNodes after gmsh 4.8.4 meshes this script (gmsh -1)
Printf("within 5 percent: %g", Fabs(Mesh.NbNodes - gmsh_nodes) <= 0.05 * gmsh_nodes);   // expect: within 5 percent: 1
Printf("%g nodes", Mesh.NbNodes);   // expect: 302 nodes
