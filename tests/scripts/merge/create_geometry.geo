// CreateGeometry on a merged MSH 2.2 square (square_fine22.msh: points 1-4, curves 21-24,
// surface 31, meshed at size 0.5: 30 nodes): the discrete curves get their polyline as
// geometry and the flat surface its plane, so that both are remeshed with their tags at
// size 1. The boundary: gmsh 4.8.4 -0. The mesh is ours: the same 1D mesh as Gmsh's (2
// segments a side, gmsh -2), where Gmsh's 2D mesher puts 4 nodes inside (12 nodes, 14
// triangles) and ours 1.
Merge "square_fine22.msh";
CreateTopology;
CreateGeometry;
b[] = Boundary{Surface{31};};
Printf("surface 31 bounded by %g curves", #b[]);   // expect: surface 31 bounded by 4 curves
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 9 nodes, 8 triangles
