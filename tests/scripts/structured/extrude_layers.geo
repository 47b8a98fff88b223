// Extrude with Layers makes Gmsh 4.8.4's structured mesh: n layers of quadrangles with
// Recombine, each cell cut into two triangles without; a rotation about an axis through
// an end point closes the first column into triangles; the top of an extruded surface
// copies the source surface's mesh. Counts: gmsh 4.8.4 -2 on this script (Mesh 2 below).
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25};
Line(1) = {1, 2};                                   // 4 segments
a[] = Extrude {0, 1, 0} { Curve{1}; Layers{5}; Recombine; };
Point(103) = {2, 0, 0, 0.25}; Point(104) = {3, 0, 0, 0.25};
Line(10) = {103, 104};
b[] = Extrude {0, 0, 1} { Curve{10}; Layers{{2, 3}, {0.5, 1}}; };
Point(205) = {0, 0, 5, 0.5}; Point(206) = {1, 0, 5, 0.5};
Line(20) = {205, 206};                                  // 2 segments
c[] = Extrude {{0, 0, 1}, {0, 0, 5}, Pi/2} { Curve{20}; Layers{6}; Recombine; };
Point(307) = {0, 0, 9, 0.5}; Point(308) = {1, 0, 9, 0.5}; Point(309) = {1, 1, 9, 0.5};
Line(30) = {307, 308}; Line(31) = {308, 309}; Line(32) = {309, 307};
Curve Loop(33) = {30, 31, 32}; Plane Surface(34) = {33};
d[] = Extrude {0, 0, 1} { Surface{34}; Layers{3}; Recombine; };
Mesh 2;
Printf("%g triangles, %g quadrangles", Mesh.NbTriangles, Mesh.NbQuadrangles);   // expect: 60 triangles, 47 quadrangles
Printf("%g nodes", Mesh.NbNodes);   // expect: 105 nodes
