// CreateGeometry on a merged square with a square hole (annulus22.msh: outer curves 21-24,
// hole curves 25-28, surface 31): the plane surface it makes has the enclosing chain of
// curves as its outer loop and the other as a hole, so that Boundary lists all eight
// (gmsh 4.8.4 -0) and the remeshed surface leaves the hole empty: at size 1, 16 outer and
// 4 hole boundary nodes and 8 inside, 2 x 8 + 20 triangles; the counts are ours (Gmsh 4.8.4
// meshes the discrete surface denser inside: 48 nodes, 72 triangles).
Merge "annulus22.msh";
CreateTopology;
CreateGeometry;
b[] = Boundary{Surface{31};};
Printf("surface 31 bounded by %g curves", #b[]);   // expect: surface 31 bounded by 8 curves
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 28 nodes, 36 triangles
