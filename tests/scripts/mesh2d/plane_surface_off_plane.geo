// A Plane Surface whose boundary lies a little off one plane (one corner raised by 1e-4,
// about 2e-5 of the square's size off the loop's plane, as in Gmsh's 2D benchmarks
// TieAnchor520 and predator): Gmsh meshes a Plane Surface in its mean plane and only checks,
// in a debug message, that no point is off by more than 1e-3 of its size. We mesh it in
// that plane too, with a warning saying how far. `gmsh -2` of this script (Gmsh 4.8.4):
// 944 triangles; ours must come within 15%.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.05}; Point(2) = {1, 0, 0, 0.05}; Point(3) = {1, 1, 1e-4, 0.05}; Point(4) = {0, 1, 0, 0.05};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh 2;   // expect warning: 12:1: mesh-warning: surface 1: the boundary lies up to 2.5e-05 off the surface's plane (more than Geometry.Tolerance; 1.8e-05 of its size) near (0, 0, 0): meshed in that plane, as Gmsh meshes a Plane Surface in its mean plane
Printf("%g", Fabs(Mesh.NbTriangles - 944) <= 0.15 * 944);   // expect: 1
