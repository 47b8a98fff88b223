// A small model on a PolarSphere of radius 2 centred at (1, 0, 0): a BSpline island inside
// a Spline-and-Line outer loop, a Plane Surface on the sphere, and queries on it.
Point(1) = {1, 0, 0};
Point(2) = {1, 0, 2};
PolarSphere(1) = {1, 2};
Point(3) = {-0.5, -0.5, 0};
Point(4) = {0.5, -0.5, 0};
Point(5) = {0.5, 0.5, 0};
Point(6) = {-0.5, 0.5, 0};
Point(7) = {0, 0.6, 0};
Line(1) = {3, 4};
Spline(2) = {4, 5};
Line(3) = {5, 7, 6};
Line(4) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4};
For i In {0:5}
  Point(10 + i) = {0.1 * Cos(i * Pi / 3), 0.1 * Sin(i * Pi / 3), 0};
EndFor
BSpline(5) = {10:15, 10};
Curve Loop(2) = {5};
Plane Surface(1) = {1, 2};
b[] = Boundary{ Surface{1}; };
Printf("%g %g %g %g %g %g", #b[], b[0], b[1], b[3], b[4], newreg);
p[] = Point{7};
Printf("%.9f %.9f %.9f", p[0], p[1], p[2]);
p[] = Point{12};
Printf("%.9f %.9f %.9f", p[0], p[1], p[2]);
e[] = Boundary{ Curve{5}; };
Printf("%g %g", e[0], e[1]);
q[] = Point In BoundingBox{0.9, -1, 1.5, 1.5, 1, 2.1};
Printf("%g", #q[]);
t[] = Translate{0, 0, 0}{ Duplicata{ Curve{5}; } };
Printf("%g %g", #t[], t[0]);
Physical Surface("sea") = {1};
Physical Curve("coast") = {5};
Printf(StrCat(Physical Surface{1}, " ", Physical Curve{2}));
// gmsh 4.8.4 -0 output:
// expect: 5 1 2 4 -5 6
// expect: 1.000000000 -1.764705882 0.941176471
// expect: 1.198019802 -0.342980358 1.960396040
// expect: 10 10
// expect: 4
// expect: 1 6
// expect: sea coast
