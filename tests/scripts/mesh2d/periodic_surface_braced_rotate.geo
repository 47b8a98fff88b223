// Periodic Surface{target} = {source} Rotate{{axis}, {point}, angle}: surface 2, the
// quarter annulus of surface 1 turned a quarter turn about z through (1, 0, 0), copies its
// mesh: both have the same triangles, surface 2's each surface 1's turned.
// 274 each (gmsh 4.8.4 -2: 282 each, 564).
r1 = 0.5; r2 = 1; c = 1;
Point(1) = {c, 0, 0, 0.05};
Point(2) = {c + r1, 0, 0, 0.05}; Point(3) = {c + r2, 0, 0, 0.1};
Point(4) = {c, r2, 0, 0.1}; Point(5) = {c, r1, 0, 0.05};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(6) = {c - r1, 0, 0, 0.3}; Point(7) = {c - r2, 0, 0, 0.3};
Circle(6) = {4, 1, 7}; Line(7) = {7, 6}; Circle(8) = {6, 1, 5};
Curve Loop(2) = {-3, 6, 7, 8}; Plane Surface(2) = {2};
Periodic Surface {2} = {1} Rotate {{0, 0, 1}, {c, 0, 0}, Pi / 2};
Mesh 2;
Printf("%g triangles", Mesh.NbTriangles);
// expect: 548 triangles
