// "..." is Gmsh's other spelling of ':' (one token, tDOTS, in Gmsh 4.8.4's lexer): lists,
// ranges with a step, loops and Spline point lists as in Gmsh's naca12_2d.geo.
a[] = {1 ... 4};
Printf("%g %g %g", #a[], a[0], a[3]);
b[] = {10 ... 4 ... -3};
Printf("%g %g %g", #b[], b[1], b[2]);
s = 0;
For i In {0 ... 3}
  s += i;
EndFor
Printf("%g", s);
c = 1 ? 5 ... 6;
Printf("%g", c);
For i In {1 ... 6}
  Point(i) = {Cos(i), Sin(i), 0, 0.1};
EndFor
Spline(1) = {1 ... 6};
p[] = PointsOf{Curve{1};};
Printf("%g %g", p[0], p[1]);
// gmsh 4.8.4 -0 output:
// expect: 4 1 4
// expect: 3 7 4
// expect: 6
// expect: 5
// expect: 1 6
