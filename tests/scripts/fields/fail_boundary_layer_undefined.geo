// 'BoundaryLayer Field' naming no field.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
BoundaryLayer Field = 3;
Mesh 2;
// expect error: 6:1: missing-field
