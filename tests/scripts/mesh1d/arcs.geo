// 1D node counts on circle and ellipse arcs against gmsh 4.8.4 -1, including arcs so
// coarse that Mesh.MinimumCircleNodes decides.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Point(3) = {0, 1, 0, 0.1};
Point(4) = {-1, 0, 0, 0.3};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Point(5) = {10, 0, 0, 100};
Point(6) = {11, 0, 0, 100};
Point(7) = {10, 1, 0, 100};
Circle(3) = {6, 5, 7};
Point(8) = {0, 5, 0, 0.05};
Point(9) = {2, 5, 0, 0.05};
Point(10) = {0, 5.5, 0, 0.05};
Ellipse(4) = {9, 8, 9, 10};
Mesh.MinimumCircleNodes = 13;
Point(11) = {20, 0, 0, 100};
Point(12) = {21, 0, 0, 100};
Point(13) = {20, 1, 0, 100};
Circle(5) = {12, 11, 13};
Mesh 1;
gmsh_nodes = 82;   // Mesh.NbNodes after gmsh 4.8.4 meshes this script (gmsh -1)
Printf("within 5 percent: %g", Fabs(Mesh.NbNodes - gmsh_nodes) <= 0.05 * gmsh_nodes);   // expect: within 5 percent: 1
Printf("%g nodes", Mesh.NbNodes);   // expect: 82 nodes
