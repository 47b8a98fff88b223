// A Plane Surface whose loops lie side by side, none inside another. Gmsh 4.8.4 accepts it and
// meshes the inside of one loop only: here the middle square (118 triangles with -save_all),
// in whatever order the loops are listed, because it takes the loop its Delaunay edge list
// meets first (Mesh/meshGFace.cpp, meshGenerator). Nothing in the script picks that loop, so
// we stop and say what Gmsh would do.
For i In {0:2}
  Point(4 * i + 1) = {5 * i - 1, -1, 0, 0.3}; Point(4 * i + 2) = {5 * i + 1, -1, 0, 0.3};
  Point(4 * i + 3) = {5 * i + 1, 1, 0, 0.3}; Point(4 * i + 4) = {5 * i - 1, 1, 0, 0.3};
  Line(4 * i + 1) = {4 * i + 1, 4 * i + 2}; Line(4 * i + 2) = {4 * i + 2, 4 * i + 3};
  Line(4 * i + 3) = {4 * i + 3, 4 * i + 4}; Line(4 * i + 4) = {4 * i + 4, 4 * i + 1};
  Curve Loop(i + 1) = {4 * i + 1 : 4 * i + 4};
EndFor
Plane Surface(1) = {3, 1, 2};
// expect error: 13:1: hole-outside: plane surface 1: hole (curve loop 1) is not inside the outer curve loop 3: Gmsh 4.8.4 would mesh the inside of just one of the loops that no other encloses, picked by its triangulation's edge order and not by the list; give each region a plane surface of its own
