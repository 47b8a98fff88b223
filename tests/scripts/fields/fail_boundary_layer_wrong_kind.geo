// 'BoundaryLayer Field' must name a BoundaryLayer field.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = Box;
BoundaryLayer Field = 1;
Mesh 2;
// expect error: 7:1: bad-field-value: 'BoundaryLayer Field = 1' names a Box field: it must be a BoundaryLayer field
