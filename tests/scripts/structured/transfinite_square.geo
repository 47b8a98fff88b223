// Transfinite Curve / Surface on a rectangle: n x m nodes, the
// grid's triangles and, recombined, its quadrangles; node and element counts as Gmsh's.
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 9;
Transfinite Curve{2, -4} = 5 Using Progression 1.3;
Transfinite Surface{1};
Mesh 2;
Printf("%g nodes, %g triangles, %g quadrangles", Mesh.NbNodes, Mesh.NbTriangles, Mesh.NbQuadrangles);
// expect: 45 nodes, 64 triangles, 0 quadrangles
Recombine Surface{1};
Mesh 2;
Printf("%g nodes, %g triangles, %g quadrangles", Mesh.NbNodes, Mesh.NbTriangles, Mesh.NbQuadrangles);
// expect: 45 nodes, 0 triangles, 32 quadrangles
