// A transfinite surface with a hole: a grid has one loop, so the hole count is the error.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Point(5) = {0.4, 0.4, 0, 0.1}; Point(6) = {0.6, 0.4, 0, 0.1}; Point(7) = {0.5, 0.6, 0, 0.1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};
Curve Loop(2) = {5, 6, 7};
Plane Surface(1) = {1, 2};
Transfinite Surface{1};
Mesh 2;
// expect error: 10:1: mesh-error: surface 1: is transfinite but has 1 hole
// compare_with_gmsh: skip
