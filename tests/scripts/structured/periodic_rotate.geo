// Periodic Curve with Rotate {{axis}, {point}, angle}: a quarter turn about the square's
// centre takes curve 1 onto curve 4, which gets its nodes; curves 2 and 3 then copy
// curve 4 and curve -1 (a copy of a copy waits for its source). Counts: gmsh 4.8.4 -0.
Point(1) = {0, 0, 0, 0.02}; Point(2) = {1, 0, 0, 0.2};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Periodic Curve {4} = {1} Rotate {{0, 0, 1}, {0.5, 0.5, 0}, -Pi/2};
Periodic Curve {2, 3} = {-4, -1};
Mesh 1;
Printf("%g nodes", Mesh.NbNodes);   // expect: 52 nodes
