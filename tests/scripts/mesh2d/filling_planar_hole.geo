// A filling Surface whose boundary is planar, with a triangular hole: meshed as a Plane
// Surface in its boundary's plane (mesh/face_filling.h), the hole cut out. `gmsh -2` of
// this script (Gmsh 4.8.4, its default Frontal-Delaunay): 1100 triangles, 600 nodes; ours
// must come within 15%.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.1}; Point(2) = {2, 0, 0, 0.1}; Point(3) = {2.5, 1, 0, 0.1}; Point(4) = {0, 1.2, 0, 0.1};
Point(5) = {0.8, 0.4, 0, 0.04}; Point(6) = {1.2, 0.4, 0, 0.04}; Point(7) = {1.0, 0.7, 0, 0.04};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7};
Surface(1) = {1, 2};
Mesh 2;
Printf("%g", Fabs(Mesh.NbTriangles - 1100) <= 0.15 * 1100);   // expect: 1
Printf("%g", Fabs(Mesh.NbNodes - 600) <= 0.15 * 600);   // expect: 1
