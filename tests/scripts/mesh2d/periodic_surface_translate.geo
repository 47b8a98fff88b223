// Periodic Surface without a transform: surface 2 (a unit square 3 to the right, its
// corners asking for much coarser sizes) copies surface 1's mesh, the translation found
// from the paired curves' end points. Its own sizes would give it far fewer triangles (348
// for both surfaces without the statement); as a copy it has as many as surface 1's 340
// (gmsh 4.8.4 -2: 348 each, 696).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.05}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Point(5) = {3, 0, 0, 0.5}; Point(6) = {4, 0, 0, 0.5}; Point(7) = {4, 1, 0, 0.5}; Point(8) = {3, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {8, 7}; Line(8) = {5, 8};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -7, -8}; Plane Surface(2) = {2};
Periodic Surface 2 {5, 6, -7, -8} = 1 {1, 2, 3, 4};
Mesh 2;
Printf("%g triangles", Mesh.NbTriangles);
// expect: 680 triangles
