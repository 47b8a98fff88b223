// MeshAlgorithm Surface{1} = 3 (Gmsh's "initial mesh only"): a unit square with 10 edges a
// side is triangulated from its 40 boundary nodes alone: 38 triangles, no node inside.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
MeshAlgorithm Surface{1} = 3;
Mesh 2;
Printf("%g %g", Mesh.NbNodes, Mesh.NbTriangles);
// gmsh 4.8.4 -0 output:
// expect: 40 38
