// `Compound Curve{c};` of one curve: Gmsh 4.8.4 meshes it as a discrete curve all the same,
// and a discrete curve takes at least 2 segments (Geo/discreteEdge.h): a line 0.5 long at
// size 1, 1 segment alone, gets 2. Output: gmsh 4.8.4 -1 (nodes of the compound curve).
Point(1) = {0, 0, 0, 1};
Point(2) = {0.5, 0, 0, 1};
Line(1) = {1, 2};
Point(3) = {0, 1, 0, 1};
Point(4) = {0.5, 1, 0, 1};
Line(2) = {3, 4};
Compound Curve{1};
Mesh 1;
Printf("%g", Mesh.NbNodes);   // expect: 5
