// `Compound Surface{...};`: two squares side by side meshed as one, across the line they
// share, each triangle classified back on its square. Gmsh 4.8.4 (`gmsh -2`, by hand):
// 126 triangles (67 on surface 1, 59 on surface 2).
// compare_with_gmsh: skip (Gmsh's node count also holds the shared line's own mesh)
lc = 0.2;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {2, 0, 0, lc}; Point(6) = {2, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Compound Surface{1, 2};
Physical Surface("both") = {1, 2};
Mesh 2;
Printf("%g", Fabs(Mesh.NbTriangles - 126) <= 0.1 * 126);   // expect: 1
