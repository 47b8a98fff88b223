// Within Mesh.MaxElements the mesh is what it is without the budget: a tight budget just
// above the square's triangle count still meshes it.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh 2;
n = Mesh.NbTriangles;
Mesh.MaxElements = 400;
Mesh 2;
Printf("%g", Mesh.NbTriangles == n && n > 200);   // expect: 1
// compare_with_gmsh: skip
