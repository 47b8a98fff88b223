// Merge of an MSH 2.2 file: its point, line and triangle elements become discrete points
// 11-14, curves 21-24 and surface 31 (meshed as they are: 6 nodes, 5 triangles); a
// triangle drawn beside it starts and ends at two merged points (one edge per line: a
// merged point has no size) and is bounded by merged curve 22. Counts: gmsh 4.8.4 -0.
Merge "square22.msh";
CreateTopology;
p[] = Point{:};
c[] = Curve{:};
Printf("%g points, %g curves", #p[], #c[]);   // expect: 4 points, 4 curves
Point(1) = {2, 0, 0, 10};
Line(1) = {12, 1};
Line(2) = {1, 13};
Transfinite Curve{1, 2} = 2;
Curve Loop(1) = {1, 2, -22};
Plane Surface(1) = {1};
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 7 nodes, 6 triangles
