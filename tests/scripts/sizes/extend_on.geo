// Mesh.MeshSizeExtendFromBoundary = 1 (the default): a unit square whose corners ask for
// 0.02 and no other size; the 1D sizes extend into the face. Gmsh 4.8.4: 5828 triangles.
Point(1) = {0, 0, 0, 0.02}; Point(2) = {1, 0, 0, 0.02}; Point(3) = {1, 1, 0, 0.02}; Point(4) = {0, 1, 0, 0.02};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4}; Plane Surface(1) = {1};
Mesh 2;
Printf("within 15 percent of gmsh's 5828 triangles: %g", Fabs(Mesh.NbTriangles - 5828) < 0.15 * 5828);  // expect: within 15 percent of gmsh's 5828 triangles: 1
