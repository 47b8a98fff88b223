// A Plane Surface whose corner lies 0.1 off the plane of the others (about 2% of its size):
// beyond the 1e-3 of its size that Gmsh checks (Gmsh would mesh it all the same, in its mean
// plane, with a debug message), so it is taken for a mistake: a located error at Mesh.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0.1, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh 2;
// expect error: 8:1: mesh-error: surface 1: the boundary is not planar (off its plane by more than 0.001 of its size, the bound Gmsh checks) near (0, 0, 0)
