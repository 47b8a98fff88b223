// A ratio below 1 would never reach the thickness: refused where it is set.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1};
Field[1].Ratio = 0.8;
BoundaryLayer Field = 1;
Mesh 2;
// expect error: 8:1: bad-field-value: Field[1] (BoundaryLayer): option 'Ratio': must be at least 1 (each layer at least as high as the one before), not 0.8
