// A point embedded on the boundary: its node lies on an edge of curve 1, the place in x, y, z.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(5) = {0.5, 0, 0, 0.2};
Point{5} In Surface{1};
Mesh 2;
// expect error: 8:1: mesh-error: surface 1: a boundary node lies on an edge of curve 1 near (0.5, 0, 0)
// compare_with_gmsh: skip
