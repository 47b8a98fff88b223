// Tag 0 for a point and for physical groups: Gmsh accepts it, and so do we, with a warning.
Point(0) = {0, 0, 0, 0.5};
Point(1) = {1, 0, 0, 0.5};
Point(2) = {0, 1, 0, 0.5};
Line(1) = {0, 1}; Line(2) = {1, 2}; Line(3) = {2, 0};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Surface(0) = {1};
Physical Point(0) = {0};
p[] = Point{0};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 0 0 0
q[] = PointsOf{Curve{1};};
Printf("%g %g", q[0], q[1]);  // expect: 0 1
g[] = Physical Surface{0};
Printf("%g", g[0]);  // expect: 1
Printf("%g", newp);  // expect: 3
// expect warning: 2:1: gmsh-compat: point tag 0: Gmsh accepts it; so do we, but tags are meant to be positive
// expect warning: 8:1: gmsh-compat: physical group tag 0: Gmsh accepts it; so do we, but tags are meant to be positive
// expect warning: 9:1: gmsh-compat: physical group tag 0: Gmsh accepts it; so do we, but tags are meant to be positive
