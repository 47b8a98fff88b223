// Periodic Curve with Translate: the transform maps curve 1's end points onto curve 3's
// (reversed here, whatever the sign says) and places the copied nodes. Counts: gmsh
// 4.8.4 -0.
Point(1) = {0, 0, 0, 0.02}; Point(2) = {1, 0, 0, 0.2};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Periodic Curve {3} = {1} Translate {0, 1, 0};
Mesh 1;
Printf("%g nodes", Mesh.NbNodes);   // expect: 54 nodes
