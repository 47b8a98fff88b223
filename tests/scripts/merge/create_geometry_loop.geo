// A loop of remeshed discrete curves (CreateGeometry on square22.msh: curve 22 runs from
// point 12 to point 13) written with the wrong sign on curve 22: Gmsh neither sorts nor
// checks a loop of discrete curves and meshes it all the same; we reverse curve 22 in it
// with a gmsh-compat warning. The node count is ours (Gmsh's 2D mesher puts more inside:
// 18 nodes, gmsh 4.8.4 -0).
Merge "square22.msh";
CreateTopology;
CreateGeometry;
Point(1) = {2, 0.5, 0, 10};
Line(1) = {12, 1};
Line(2) = {1, 13};
Curve Loop(1) = {1, 2, 22};   // expect warning: 12:1: gmsh-compat: curve loop 1 holds discrete curves, whose loops Gmsh 4.8.4 neither sorts nor checks (it meshes their edges whatever their signs): we reverse curve 22 (and any other that needs it) so that the loop closes
Plane Surface(1) = {1};
Mesh.MeshSizeMin = 0.5;
Mesh.MeshSizeMax = 0.5;
Mesh 2;
Printf("%g nodes", Mesh.NbNodes);   // expect: 15 nodes
