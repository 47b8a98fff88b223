// Gmsh's smoothing of the 1D size (Mesh.SmoothRatio = 1.8: the size grows by at most
// sqrt(1.8) - 1 per unit length along a curve): steep point sizes on lines and a
// B-spline, and a size field with a sharp step along the third line; node count against gmsh 4.8.4 -1.
Point(1) = {0, 0, 0, 0.01};
Point(2) = {1, 0, 0, 1};
Line(1) = {1, 2};
Point(3) = {0, 2, 0, 0.5};
Point(4) = {0.5, 2.3, 0, 0.002};
Point(5) = {1.5, 2.1, 0, 0.3};
Point(6) = {2.5, 2.6, 0, 0.3};
BSpline(2) = {3, 4, 5, 6};
Point(7) = {0, 4, 0};
Point(8) = {3, 4, 0};
Line(3) = {7, 8};
Field[1] = MathEval;
Field[1].F = "0.005 + 0.5 / (1 + exp(40 * (x - 1.5) + 100 * (y - 3.5)))";
Background Field = 1;
Mesh 1;
gmsh_nodes = 553;   // Mesh.NbNodes after gmsh 4.8.4 meshes this script (gmsh -1)
Printf("within 5 percent: %g", Fabs(Mesh.NbNodes - gmsh_nodes) <= 0.05 * gmsh_nodes);   // expect: within 5 percent: 1
Printf("%g nodes", Mesh.NbNodes);   // expect: 553 nodes
