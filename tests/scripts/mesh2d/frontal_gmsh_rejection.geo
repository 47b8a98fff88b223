// On a flat model front2d refuses the points Gmsh 4.8.4 refuses (docs/kernel.md,
// Frontal-Delaunay: closer than half the size to a node of the point's cavity, or 0.4 of it
// to a boundary edge's line), so a graded mesh gets Gmsh's triangle count. A unit square
// at 0.2 around a circular hole at 0.02: gmsh 4.8.4 -2 makes 310 triangles; we made 328
// without the rule and make 304 with it.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Point(5) = {0.5, 0.5, 0, 0.02}; Point(6) = {0.6, 0.5, 0, 0.02}; Point(7) = {0.5, 0.6, 0, 0.02};
Point(8) = {0.4, 0.5, 0, 0.02}; Point(9) = {0.5, 0.4, 0, 0.02};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 8}; Circle(7) = {8, 5, 9}; Circle(8) = {9, 5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Mesh 2;
Printf("%g", Abs(Mesh.NbTriangles - 310) <= 10);   // expect: 1
