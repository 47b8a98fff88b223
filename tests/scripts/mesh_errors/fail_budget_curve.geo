// A size factor of 1e-20 (-clscale 1e-20) asks one curve for 1e20 nodes: refused before
// any node is placed (no double-to-int overflow, no 4-triangle mesh).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh.MeshSizeFactor = 1e-20;
Mesh 1;   // expect error: 8:1: limit-exceeded
// compare_with_gmsh: skip
