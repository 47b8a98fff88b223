// More than 1000 layers (Size 1e-9, Ratio 1, Thickness 1): refused at the Thickness.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1};
Field[1].Size = 1e-9;
Field[1].Ratio = 1;
Field[1].Thickness = 1;
BoundaryLayer Field = 1;
Mesh 2;
// expect error: 10:1: bad-field-value
