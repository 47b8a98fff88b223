// Translate, Rotate, Dilate and Symmetry of points and curves (as statements and as
// expressions returning the moved tags), and Duplicata of points and curves.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
t[] = Translate{1, 2, 3}{ Point{3}; };
Printf("%g %g", #t[], t[0]);  // expect: 1 3
p[] = Point{3};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 2 3 3
Translate{-1, -2, -3}{ Point{3}; }
p[] = Point{3};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 1 1 0
Rotate{{0, 0, 1}, {0, 0, 0}, Pi/2}{ Point{2}; }
p[] = Point{2};
Printf("%.6f %.6f %.6f", p[0], p[1], p[2]);  // expect: 0.000000 1.000000 0.000000
Dilate{{1, 1, 1}, 3}{ Point{1}; }
p[] = Point{1};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: -2 -2 -2
Dilate{{0, 0, 0}, {1, 2, 4}}{ Point{1}; }
p[] = Point{1};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: -2 -4 -8
Symmetry{1, 0, 0, -1}{ Point{1}; }
p[] = Point{1};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 4 -4 -8
Point(4) = {5, 5, 5};
d[] = Duplicata{ Point{4}; };
Printf("%g %g %g", #d[], d[0], newp);  // expect: 1 5 6
p[] = Point{d[0]};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 5 5 5
d[] = Translate{0, 0, 1}{ Duplicata{ Point{4}; } };
p[] = Point{d[0]};
Printf("%g %g %g %g", d[0], p[0], p[1], p[2]);  // expect: 6 5 5 6
c[] = Translate{0, 0, 10}{ Duplicata{ Curve{1, 2}; } };
Printf("%g %g %g %g", #c[], c[0], c[1], newreg);  // expect: 2 3 4 5
b[] = Boundary{ Curve{c[1]}; };
p[] = Point{b[1]};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 1 1 10
Translate{0, 0, 1}{ Curve{2}; }
p[] = Point{3};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 1 1 1
