// Delete Model and Delete All destroy the geometry, its tags and the fields: newp, newreg
// and newf start again at 1 (gmsh 4.8.4).
Point(1) = {0,0,0}; Point(2) = {1,0,0}; Line(1) = {1,2};
Physical Curve(5) = {1};
Physical Point(6) = {1};
Field[3] = Box;
Printf("%g %g %g", newreg, newp, newf);
Delete Model;
a[] = Point{:}; Printf("%g %g %g %g", #a[], newp, newreg, newf);
Point(1) = {0,0,0}; Physical Point(2) = {1};
Field[1] = Box;
Printf("%g %g %g", newreg, newp, newf);
Delete All;
Printf("%g %g %g", newp, newf, newreg);
// gmsh 4.8.4 -0 output:
// expect: 7 3 4
// expect: 0 1 1 1
// expect: 3 2 2
// expect: 1 1 1
