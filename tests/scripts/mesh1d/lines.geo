// 1D node counts on straight lines against gmsh 4.8.4 -1: constant lc (Gmsh's example:
// a unit segment with lc = 0.5 has 2 elements), graded lc, an end point without lc
// (interpolated towards MAX_LC, capped by the bounding box), a polyline.
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Line(1) = {1, 2};
Point(3) = {0, 1, 0, 0.01};
Point(4) = {1, 1, 0, 0.1};
Line(2) = {3, 4};
Point(5) = {3, 0, 0};
Line(3) = {2, 5};
Point(6) = {0, 2, 0, 0.05};
Point(7) = {0.5, 2.5, 0, 0.2};
Point(8) = {1, 2, 0, 0.05};
Line(4) = {6, 7};
Line(5) = {7, 8};
Mesh 1;
gmsh_nodes = 47;   // Mesh.NbNodes after gmsh 4.8.4 meshes this script (gmsh -1)
Printf("within 5 percent: %g", Fabs(Mesh.NbNodes - gmsh_nodes) <= 0.05 * gmsh_nodes);   // expect: within 5 percent: 1
