// On a PolarSphere, as in Gmsh's benchmarks/2d/world.geo: an island and an outer coast
// written as (u,v) Points with a point repeated at the same place under another tag (as a
// polygon export writes a ring's closing point). The island's zero-length Line and the
// coast's B-spline piece of repeated points collapse, as in Gmsh, and the ocean meshes.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
PolarSphere(1) = {1, 2};
lc = 0.05;
n = 12;
For i In {0:n - 1}
  Point(10 + i) = {0.8 * Cos(2 * Pi * i / n), 0.8 * Sin(2 * Pi * i / n), 0, lc};
EndFor
Point(30) = {0.8, 0, 0, lc};   // point 10 again, under another tag
For i In {0:n - 1}
  Line(10 + i) = {10 + i, i < n - 1 ? 11 + i : 30};
EndFor
Line(30) = {30, 10};           // zero length
Curve Loop(1) = {10:10 + n - 1, 30};
For i In {0:3}
  Point(40 + i) = {0.2 * Cos(Pi * i / 2) + 0.1, 0.2 * Sin(Pi * i / 2), 0, lc};
EndFor
Point(44) = {0.3, 0, 0, lc}; Point(45) = {0.3, 0, 0, lc};   // point 40 twice more
BSpline(40) = {40, 41, 42, 43, 44};
BSpline(41) = {44, 45, 40};    // all three control points at one place
Curve Loop(2) = {40, 41};
Plane Surface(1) = {1, 2};
Physical Surface(1) = {1};
Mesh 2;
Printf("%g", Mesh.NbTriangles > 100);
// expect warning: 16:1: gmsh-compat: Line 30 has zero length (points 30 and 10 are at the same place): Gmsh collapses it, and so do we: both points get one mesh node and the curve no mesh edge
// expect warning: 23:1: gmsh-compat: BSpline 41 has zero length (points 44 and 40 are at the same place): Gmsh collapses it, and so do we: both points get one mesh node and the curve no mesh edge
// gmsh 4.8.4 -0 output:
// expect: 1
