// Gmsh's benchmark of a compound with an embedded curve across the surfaces' shared
// curves (benchmarks/2d/embedded_compound.geo, flattened: all points at z = 0). Three
// filling surfaces in one plane meshed as one, with two compound curves on its boundary.
// Gmsh 4.8.4 (`gmsh -2`, by hand): 896 triangles (593 on surface 1, 303 on 5, none on 10).
// compare_with_gmsh: skip (Gmsh's node count also holds the originals' own meshes)
lc = 0.1;
Point(1) = {0, 0, 0, lc};      Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};      Point(4) = {0, 1, 0, lc};
Point(5) = {0.3, 0.2, 0, lc};  Point(6) = {0, 0.01, 0., lc};
Point(7) = {0, 0.02, 0.0, lc}; Point(8) = {1, 0.05, 0.0, lc};
Point(9) = {1, 0.32, 0.0, lc};
Line(1) = {1, 2}; Line(2) = {2, 8}; Line(3) = {8, 9};
Line(4) = {9, 3}; Line(5) = {3, 4}; Line(6) = {4, 7};
Line(7) = {7, 6}; Line(8) = {6, 1}; Spline(9) = {7, 5, 9};
Line(10) = {6, 8};
Curve Loop(11) = {5, 6, 9, 4};     Surface(1) = {11};
Curve Loop(13) = {-9, 3, 10, 7}; Surface(5) = {13};
Curve Loop(15) = {-10, 2, 1, 8}; Surface(10) = {15};
Compound Curve{2, 3, 4};
Compound Curve{6, 7, 8};
Compound Surface{1, 5, 10};
Point(10) = {0.2, 0.6, 0, lc/2};
Point(11) = {0.7, 0.2, 0, lc/20};
Line(11) = {10, 11};
Curve{11} In Surface{1};
Physical Surface(1) = {1, 5, 10};
Mesh 2;
Printf("%g", Fabs(Mesh.NbTriangles - 896) <= 0.1 * 896);   // expect: 1
