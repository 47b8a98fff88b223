// Two distinct points at the same place, joined by a zero-length Line inside a loop, and
// a B-spline whose control points all coincide: Gmsh collapses such curves (both points
// get one mesh node) and meshes the surface; so do we, with a warning where each is made.
lc = 0.2;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 0, 0, lc};
Point(4) = {2, 2, 0, lc}; Point(5) = {0, 2, 0, lc}; Point(6) = {0, 2, 0, lc}; Point(7) = {0, 2, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
BSpline(5) = {5, 6, 7};
Line(6) = {7, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Physical Surface(1) = {1};
Mesh 2;
Printf("%g", Mesh.NbTriangles > 200);
// expect warning: 8:1: gmsh-compat: Line 2 has zero length (points 2 and 3 are at the same place): Gmsh collapses it, and so do we: both points get one mesh node and the curve no mesh edge
// expect warning: 11:1: gmsh-compat: BSpline 5 has zero length (points 5 and 7 are at the same place): Gmsh collapses it, and so do we: both points get one mesh node and the curve no mesh edge
// gmsh 4.8.4 -0 output (it meshes: 144 nodes, 240 triangles):
// expect: 1
