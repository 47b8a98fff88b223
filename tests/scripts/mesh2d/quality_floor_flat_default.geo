// On a flat model Mesh.QualityFloor is off unless set, so a Gmsh script meshes as in
// Gmsh: this sliver (rho 0.27) stays one triangle on its three curve edges; with the floor
// on by default its curve edges were split (4 nodes, 2 triangles).
Point(1) = {0, 0, 0, 1};
Point(2) = {0.1, 0.1, 0, 1};
Point(3) = {0.1, 0.2, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 3 nodes, 1 triangles
