// Each curve within Mesh.MaxElements but all of them together over it: refused, naming
// the curve with the most nodes.
Point(1) = {0, 0, 0, 0.01}; Point(2) = {1, 0, 0, 0.01}; Point(3) = {1, 1, 0, 0.01};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Mesh.MaxElements = 250;
Mesh 1;   // expect error: 6:1: limit-exceeded
// compare_with_gmsh: skip
