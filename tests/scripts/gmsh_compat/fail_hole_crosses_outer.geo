// A hole that crosses the outer loop is kept (Gmsh meshes the discretised curves; see
// hole_listed_first.geo), but curves that really cross stop the mesh: the 1D mesh finds
// edges that cross and reports them.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {2, 0, 0, 0.2}; Point(3) = {2, 2, 0, 0.2}; Point(4) = {0, 2, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {1.5, 0.5, 0, 0.2}; Point(6) = {2.5, 0.5, 0, 0.2}; Point(7) = {2.5, 1.5, 0, 0.2}; Point(8) = {1.5, 1.5, 0, 0.2};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Mesh 2;
// expect warning: 10:1: gmsh-compat: plane surface 1: hole (curve loop 2) crosses the outer curve loop 1: Gmsh meshes them as discretised, and so do we (the 1D mesh refuses mesh edges that cross)
// expect error: 11:1: curves-intersect
