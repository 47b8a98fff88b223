// A transfinite corner that is no point of the boundary: the surface and the point named.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Point(5) = {0.5, 0.5, 0, 0.2};
Plane Surface(1) = {1};
Transfinite Surface{1} = {1, 2, 3, 5};
Mesh 2;
// expect error: 8:1: mesh-error: surface 1: transfinite corner 5 is not a point of its boundary
// compare_with_gmsh: skip
