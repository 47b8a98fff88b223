// A 3-sided transfinite surface (corners implicit, Gmsh's degenerate fourth side) with
// Alternate diagonals, and explicit corners on a 5-curve face.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3} = 6;
Transfinite Surface{1} Alternate;
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 31 nodes, 45 triangles
Point(11) = {2, 0, 0}; Point(12) = {3, 0, 0}; Point(13) = {3, 1, 0}; Point(14) = {2, 1, 0};
Point(15) = {2, 0.5, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 15}; Line(15) = {15, 11};
Curve Loop(11) = {11, 12, 13, 14, 15};
Plane Surface(11) = {11};
Transfinite Curve{11, 13} = 5;
Transfinite Curve{12} = 7;
Transfinite Curve{14, 15} = 4;
Transfinite Surface{11} = {11, 12, 13, 14} Right;
Recombine Surface{11};
Mesh 2;
Printf("%g nodes, %g triangles, %g quadrangles", Mesh.NbNodes, Mesh.NbTriangles, Mesh.NbQuadrangles);
// expect: 66 nodes, 45 triangles, 24 quadrangles
