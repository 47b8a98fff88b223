// MeshAlgorithm Surface{s} = n; sets the 2D algorithm of those surfaces only. 3 is Gmsh's
// "initial mesh only": the boundary's triangulation, no node inside (as in its
// benchmarks/2d/only_initial_mesh.geo). Two unit squares side by side, 10 edges a side.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Point(5) = {2, 0, 0, 0.1}; Point(6) = {2, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
MeshAlgorithm Surface{2} = 3;
Mesh 2;
// Surface 1 gets nodes inside (70 on the curves), surface 2 none.
Printf("%g", Mesh.NbNodes > 70 + 50);
// gmsh 4.8.4 -0 output:
// expect: 1
