// Mesh.MeshSizeExtendFromBoundary = 0: the same square (corners at 0.02, extend_on.geo) is
// meshed inside at the model size (the bounding-box diagonal); only the triangles on the
// boundary edges stay small. Gmsh 4.8.4: 242 triangles (5828 with the extension).
Mesh.MeshSizeExtendFromBoundary = 0;
Point(1) = {0, 0, 0, 0.02}; Point(2) = {1, 0, 0, 0.02}; Point(3) = {1, 1, 0, 0.02}; Point(4) = {0, 1, 0, 0.02};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4}; Plane Surface(1) = {1};
Mesh 2;
Printf("below twice gmsh's 242 triangles: %g", Mesh.NbTriangles < 2 * 242);  // expect: below twice gmsh's 242 triangles: 1
