// Periodic Surface{target} = {source} Affine{16 numbers}: surface 2 is surface 1 mirrored
// in the plane y = 0 (a map that turns its boundary the other way round); its triangles
// are surface 1's mirrored, and turn as its own loop does.
// 287 each (gmsh 4.8.4 -2: 297 each, 594).
Point(1) = {0, 0.2, 0, 0.05}; Point(2) = {1, 0.2, 0, 0.1}; Point(3) = {0.7, 1, 0, 0.1}; Point(4) = {0.1, 0.8, 0, 0.05};
Point(5) = {0, -0.2, 0, 0.5}; Point(6) = {1, -0.2, 0, 0.5}; Point(7) = {0.7, -1, 0, 0.5}; Point(8) = {0.1, -0.8, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Periodic Surface {2} = {1} Affine {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Mesh 2;
Printf("%g triangles", Mesh.NbTriangles);
// expect: 574 triangles
