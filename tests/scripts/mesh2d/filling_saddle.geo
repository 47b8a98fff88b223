// A non-planar 4-sided filling Surface: its Coons patch on four straight sides is the
// saddle z = u (1 - v) + (1 - u) v, x = 2u, y = 2v, meshed in the patch's parameters with
// sizes measured in space (mesh/filling_map.h). `gmsh -2` of this script (Gmsh 4.8.4):
// 1072 triangles, 583 nodes; ours must come within 15%.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.1}; Point(2) = {2, 0, 1, 0.1}; Point(3) = {2, 2, 0, 0.1}; Point(4) = {0, 2, 1, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Mesh 2;
Printf("%g", Fabs(Mesh.NbTriangles - 1072) <= 0.15 * 1072);   // expect: 1
Printf("%g", Fabs(Mesh.NbNodes - 583) <= 0.15 * 583);   // expect: 1
