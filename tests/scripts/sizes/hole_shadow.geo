// The sizes extended from the boundary (Mesh.MeshSizeExtendFromBoundary, on by default) are
// interpolated in the boundary triangulation with its holes: a point behind a hole must get
// the sizes around it, not the hole's. A fine diamond (size 0.002) and a coarse triangle
// (size 1.5) are holes in a 45 x 30 box (size 5), as in Gmsh's foil_bernhard.geo.
// Gmsh 4.8.4: 1974 triangles (front2d), 2400 here; 57,096 when the location walk stopped at
// the diamond and gave its size to everything in its shadow, 4644 with the sizes interpolated
// in the boundary triangulation rather than carried by the vertices as Gmsh does.
Point(1) = {-15, -15, 0, 5}; Point(2) = {30, -15, 0, 5}; Point(3) = {30, 15, 0, 5}; Point(4) = {-15, 15, 0, 5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0, 0, 0, 0.002}; Point(6) = {0.5, -0.05, 0, 0.02}; Point(7) = {1, 0, 0, 0.002}; Point(8) = {0.5, 0.05, 0, 0.02};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Point(9) = {24.5, 3.2, 0, 1.5}; Point(10) = {26, 3.2, 0, 1.5}; Point(11) = {26, 4.7, 0, 1.5};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 9};
Curve Loop(1) = {1:4}; Curve Loop(2) = {5:8}; Curve Loop(3) = {9:11};
Plane Surface(1) = {1, 2, 3};
Mesh 2;
Printf("below 1.5 times gmsh's 1974 triangles: %g", Mesh.NbTriangles < 1.5 * 1974);  // expect: below 1.5 times gmsh's 1974 triangles: 1
