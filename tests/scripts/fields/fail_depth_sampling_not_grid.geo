// Mesh.DepthSampling = 1 averages the cells of a relief grid: with a depth field that is
// no grid it is refused at the option, before meshing.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {0, 1, 0, 0.2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = MathEval;
Field[1].F = "10";
Mesh.DepthField = 1;
Mesh.DepthSampling = 1;
Mesh 2;
// expect error: 15:1: invalid-option-value: Mesh.DepthSampling = 1 averages the cells of a relief grid: Mesh.DepthField must be a Bathymetry field with Output "depth"
