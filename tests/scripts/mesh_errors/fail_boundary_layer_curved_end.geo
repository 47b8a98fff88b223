// A layer ends at point 2, where a curved line goes on: Gmsh wants a straight one.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1}; Point(5) = {1.2, 0.25, 0, 0.1};
Line(1) = {1, 2}; Spline(2) = {2, 5, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1};
Field[1].PointsList = {1, 2};
BoundaryLayer Field = 1;
Mesh 2;
// expect error: 9:1: mesh-error: curve 2 leaves point 2, where a boundary layer ends: it must be a straight line to carry the layer points (as in Gmsh)
