// new* tags after each kind of statement, with Gmsh's OldNewReg quirk (the default):
// newl, newc, newll, news, newsl and newv all return newreg, which counts curves,
// loops, surfaces and physical groups but not points.
Printf("%g %g %g %g %g", newp, newl, newll, news, newreg);  // expect: 1 1 1 1 1
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(7) = {0, 1, 0};
Printf("%g %g %g %g %g", newp, newl, newll, news, newreg);  // expect: 8 1 1 1 1
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 7};
Line(4) = {7, 1};
Printf("%g %g %g %g %g", newp, newl, newll, news, newreg);  // expect: 8 5 5 5 5
Curve Loop(10) = {1, 2, 3, 4};
Printf("%g %g %g %g %g", newp, newl, newll, news, newreg);  // expect: 8 11 11 11 11
Plane Surface(4) = {10};
Printf("%g %g %g %g %g", newp, newl, newll, news, newreg);  // expect: 8 11 11 11 11
Physical Surface(11) = {4};
Printf("%g %g %g %g %g %g %g", newp, newl, newll, news, newreg, newsl, newv);  // expect: 8 12 12 12 12 12 12
Physical Curve("walls") = {1, 2};
Printf("%g", newreg);  // expect: 13
Geometry.OldNewReg = 0;
Printf("%g %g %g %g %g", newp, newl, newll, news, newreg);  // expect: 8 5 11 5 13
Geometry.OldNewReg = 1;
SetMaxTag Point(100);
Printf("%g", newp);  // expect: 101
Point(newp) = {2, 2, 0};
Printf("%g", newp);  // expect: 102
Line(newl) = {101, 3};
Printf("%g %g", newl, newreg);  // expect: 14 14
SetMaxTag Curve(50);
Printf("%g %g %g", newl, newreg, newp);  // expect: 51 51 102
SetMaxTag Surface(60);
Printf("%g %g", news, newreg);  // expect: 61 61
Geometry.OldNewReg = 0;
Printf("%g %g %g", newl, news, newll);  // expect: 51 61 11
Geometry.OldNewReg = 1;
