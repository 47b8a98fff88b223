// On a PolarSphere, a small outer loop round the (u,v) origin with the holes all around it
// (Gmsh's benchmarks/2d/world.geo does this: its data put the other pole at the origin).
// The sea they mean holds the projection pole, the plane's infinity: no face can hold it.
// Gmsh 4.8.4 says nothing and meshes the inside of one loop (here curve loop 1, 1003 triangles
// with -save_all); we stop and say why.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
PolarSphere(1) = {1, 2};
For i In {0:7}
  Point(10 + i) = {0.3 * Cos(Pi * i / 4), 0.3 * Sin(Pi * i / 4), 0, 0.05};
  Point(20 + i) = {2 + 0.3 * Cos(Pi * i / 4), 0.3 * Sin(Pi * i / 4), 0, 0.05};
EndFor
Spline(1) = {10:17, 10};
Spline(2) = {20:27, 20};
Curve Loop(1) = {1};
Curve Loop(2) = {2};
Plane Surface(1) = {1, 2};
// expect error: 16:1: hole-outside: plane surface 1: hole (curve loop 2) is not inside the outer curve loop 1: in the (u,v) plane of PolarSphere 1 every hole lies outside it, so the region they leave holds the projection pole (the plane's infinity), which a face cannot hold; Gmsh 4.8.4 would mesh the inside of just one of the loops, picked by its triangulation's edge order and not by the list
