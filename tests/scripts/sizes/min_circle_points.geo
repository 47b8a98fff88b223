// Mesh.MinimumCirclePoints and Mesh.MinimumCurvePoints, 4.8.4's deprecated names of
// Mesh.MinimumCircleNodes / MinimumCurveNodes, set the same variables; MinimumCirclePoints is
// per full turn: a half circle at a size far above its length gets int(0.99 + 12 / 2) = 6
// segments with 13, a full circle 13, a spline MinimumCurvePoints - 1 = 4.
Mesh.MinimumCirclePoints = 13;
Mesh.MinimumCurvePoints = 5;
Mesh.MinimumElementsPerTwoPi = 0;
Printf("%g %g %g", Mesh.MinimumCircleNodes, Mesh.MinimumCurveNodes, Mesh.MeshSizeFromCurvature);  // expect: 13 5 0
Point(1) = {0, 0, 0, 100}; Point(2) = {1, 0, 0, 100}; Point(3) = {-1, 0, 0, 100};
Circle(1) = {2, 1, 3};
Point(4) = {0, 3, 0, 100}; Point(5) = {1, 3, 0, 100}; Point(6) = {-1, 3, 0, 100};
Circle(2) = {5, 4, 6}; Circle(3) = {6, 4, 5};
Point(7) = {3, 0, 0, 100}; Point(8) = {4, 1, 0, 100}; Point(9) = {5, 0, 0, 100};
Spline(4) = {7, 8, 9};
Mesh 1;
Printf("%g nodes", Mesh.NbNodes);  // expect: 27 nodes
