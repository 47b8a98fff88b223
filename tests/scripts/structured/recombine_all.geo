// Mesh.RecombineAll pairs the triangles of every surface, with Mesh.Algorithm 8 (Gmsh's
// Frontal-Delaunay for Quads: our front2d, recombined); with RecombineAll 0 and no
// Recombine statement the same algorithm gives triangles only.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Point(5) = {2, 0, 0, 0.2}; Point(6) = {2, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Mesh.Algorithm = 8;
Mesh 2;
// 128 with Gmsh's rule for frontal points (docs/kernel.md), 140 before; gmsh 4.8.4 -2
// makes 134 with Mesh.Algorithm 6 (with 8 it crashed on this model).
Printf("%g triangles, %g quadrangles", Mesh.NbTriangles, Mesh.NbQuadrangles);   // expect: 128 triangles, 0 quadrangles
Mesh.RecombineAll = 1;
Mesh 2;
// The curves' counts made odd: more triangles, all paired.
Printf("%g triangles, %g quadrangles", Mesh.NbTriangles, Mesh.NbQuadrangles);   // expect: 0 triangles, 92 quadrangles
// compare_with_gmsh: skip
