// Mesh.MeshSizeFromCurvature = N: N elements per 2 Pi of turning on a curve, whatever the
// point sizes (here far above the radius): a circle of radius 1 in two halves gets 24
// segments here (25 nodes), 26 in Gmsh 4.8.4 (27 nodes); without it 2 x 3 segments.
Mesh.MeshSizeFromCurvature = 24;
Point(1) = {0, 0, 0, 10}; Point(2) = {1, 0, 0, 10}; Point(3) = {-1, 0, 0, 10};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 2};
Curve Loop(1) = {1, 2}; Plane Surface(1) = {1};
Mesh 1;
Printf("1D nodes within 15 percent of gmsh's 27: %g", Fabs(Mesh.NbNodes - 27) < 0.15 * 27);  // expect: 1D nodes within 15 percent of gmsh's 27: 1
