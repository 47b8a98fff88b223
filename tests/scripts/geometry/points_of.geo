// PointsOf{} (a curve gives its end points, a surface each of its points once) and
// Physical X{:} (the group tags).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 1, 0};
Point(4) = {1, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve(7) = {1, 2, 3};
Physical Curve(9) = {2};
a[] = Physical Curve{:};
Printf("%g %g %g", #a[], a[0], a[1]);  // expect: 2 7 9
p[] = PointsOf{ Curve{1, 2}; };
Printf("%g %g %g %g %g", #p[], p[0], p[1], p[2], p[3]);  // expect: 4 1 2 2 3
p[] = PointsOf{ Surface{1}; };
Printf("%g %g %g %g", #p[], p[0], p[1], p[2]);  // expect: 3 1 2 3
p[] = PointsOf{ Point{4}; Curve{-1}; };
Printf("%g %g %g %g", #p[], p[0], p[1], p[2]);  // expect: 3 4 2 1
t[] = Translate{0, 0, 1}{ Physical Curve{9}; };
Printf("%g %g", #t[], t[0]);  // expect: 1 2
q[] = Point{3};
Printf("%g %g %g", q[0], q[1], q[2]);  // expect: 0 1 1
