// Periodic Surface{target} = {source} Translate{..} (Gmsh's form with a transform): surface
// 2, a unit square 3 to the right whose own sizes would be much coarser, copies surface 1's
// mesh. Its curves are listed in another order and run other ways than surface 1's: they
// are paired by where the translation takes surface 1's points, not by the lists.
// Each surface has 340 triangles (gmsh 4.8.4 -2: 348 each, 696).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.05}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Point(5) = {3, 0, 0, 0.5}; Point(6) = {4, 0, 0, 0.5}; Point(7) = {4, 1, 0, 0.5}; Point(8) = {3, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {7, 6}; Line(6) = {8, 7}; Line(7) = {5, 8}; Line(8) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {8, -5, -6, -7}; Plane Surface(2) = {2};
Periodic Surface {2} = {1} Translate {3, 0, 0};
Mesh 2;
Printf("%g triangles", Mesh.NbTriangles);
// expect: 680 triangles
