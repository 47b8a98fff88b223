// Recombine Surface on an unstructured square: Gmsh makes the curves' node counts odd
// (Mesh.RecombinationAlgorithm 1) so that the matching pairs every triangle; the simple
// pass (0) leaves some. Counts of our mesher (Gmsh's triangulation differs).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Recombine Surface{1};
Mesh 2;
Printf("blossom-quality: %g triangles left", Mesh.NbTriangles);   // expect: blossom-quality: 0 triangles left
Printf("%g quadrangles", Mesh.NbQuadrangles);   // expect: 123 quadrangles
Mesh.RecombinationAlgorithm = 0;
Mesh 2;
// With Gmsh's rule for frontal points (docs/kernel.md) 28 and 109; before it 32 and 107;
// gmsh 4.8.4 -2 leaves 30 triangles and 106 quadrangles.
Printf("simple: %g triangles left", Mesh.NbTriangles);   // expect: simple: 28 triangles left
Printf("%g quadrangles", Mesh.NbQuadrangles);   // expect: 109 quadrangles
// compare_with_gmsh: skip
