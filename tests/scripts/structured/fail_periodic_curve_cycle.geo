// Two periodic curves copying each other: neither is meshed first, the cycle is the error.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Periodic Curve{1} = {3};
Periodic Curve{3} = {1};
Mesh 1;
// expect error: 8:1: mesh-error: periodic curve 1 copies curve 3, which is not meshed first: the periodic curves copy one another in a cycle, or the source is not a curve of the model
// compare_with_gmsh: skip
