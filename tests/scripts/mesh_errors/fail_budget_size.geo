// lc = 1e-5 on a unit square: 4e5 boundary nodes are cheap, the 2.3e10 triangles are not:
// refused from the estimate on the boundary triangulation, before any refinement.
lc = 1e-5;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh 2;   // expect error: 8:1: limit-exceeded
// compare_with_gmsh: skip
