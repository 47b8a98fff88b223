// A source surface with an embedded point and an embedded curve (Gmsh pairs them by the map
// as it pairs the boundary, and copies their nodes): surface 2, 2 to the right, has the
// same at their images and copies surface 1's mesh, both constrained by them.
// 1176 each (gmsh 4.8.4 -2: 1066 each, 2132).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Point(5) = {0.3, 0.3, 0, 0.01}; Point(6) = {0.5, 0.7, 0, 0.02}; Point(7) = {0.8, 0.5, 0, 0.02};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1}; Line(5) = {6, 7};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point{5} In Surface{1}; Curve{5} In Surface{1};
Point(11) = {2, 0, 0, 0.3}; Point(12) = {3, 0, 0, 0.3}; Point(13) = {3, 1, 0, 0.3}; Point(14) = {2, 1, 0, 0.3};
Point(15) = {2.3, 0.3, 0, 0.3}; Point(16) = {2.5, 0.7, 0, 0.3}; Point(17) = {2.8, 0.5, 0, 0.3};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11}; Line(15) = {17, 16};
Curve Loop(2) = {11, 12, 13, 14}; Plane Surface(2) = {2};
Point{15} In Surface{2}; Curve{15} In Surface{2};
Periodic Surface {2} = {1} Translate {2, 0, 0};
Mesh 2;
Printf("%g triangles", Mesh.NbTriangles);
// expect: 2352 triangles
