// Mesh.MeshSizeFromPoints = 0: the point sizes are ignored; the curves and the face get the
// model size clamped by Mesh.MeshSizeMax: 246 triangles here, 242 in Gmsh 4.8.4 (the
// corner sizes 0.01 would give thousands).
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeMax = 0.1;
Point(1) = {0, 0, 0, 0.01}; Point(2) = {1, 0, 0, 0.01}; Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4}; Plane Surface(1) = {1};
Mesh 2;
Printf("within 15 percent of gmsh's 242 triangles: %g", Fabs(Mesh.NbTriangles - 242) < 0.15 * 242);  // expect: within 15 percent of gmsh's 242 triangles: 1
