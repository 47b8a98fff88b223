// Merge of an MSH 4.1 file with a physical group: its entities are discrete points,
// curves and a surface as in MSH 2.2 (merge_msh22.geo), and its curve group the model's.
// Meshing keeps its elements. Output: gmsh 4.8.4 -0.
Merge "square41.msh";
c[] = Physical Curve{5};
Printf("coast: curve %g", c[0]);   // expect: coast: curve 21
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);   // expect: 6 nodes, 5 triangles
