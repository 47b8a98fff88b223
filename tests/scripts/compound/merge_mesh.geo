// Merging a mesh (merge_square.msh, a unit square in four triangles, MSH 4.1 written by
// gmsh 4.8.4): Gmsh makes its elements discrete points, curves and surfaces, and so do we
// (merge_mesh.cpp); meshing keeps them as they are. Output: gmsh 4.8.4 -0.
Merge "merge_square.msh";
p[] = Point{:};
c[] = Curve{:};
Printf("%g points, %g curves", #p[], #c[]);   // expect: 4 points, 4 curves
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 5 nodes, 4 triangles
