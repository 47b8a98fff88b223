// Split Curve replaces a curve by its pieces between the given control points;
// X In BoundingBox{} lists the entities inside a box.
For i In {1:5}
  Point(i) = {i, Sin(i), 0};
EndFor
Spline(1) = {1:5};
Split Curve{1} Point{3};
c[] = Curve{:};
Printf("%g %g %g", #c[], c[0], c[1]);
b[] = Boundary{ Curve{c[0]}; };
Printf("%g %g", b[0], b[1]);
b[] = Boundary{ Curve{c[1]}; };
Printf("%g %g", b[0], b[1]);
p[] = Point In BoundingBox{0.5, -2, -1, 3.5, 2, 1};
Printf("%g %g %g %g", #p[], p[0], p[1], p[2]);
q[] = Curve In BoundingBox{0, -2, -1, 3.5, 2, 1};
Printf("%g %g", #q[], q[0]);
// gmsh 4.8.4 -0 output:
// expect: 2 2 3
// expect: 1 3
// expect: 3 5
// expect: 3 1 2 3
// expect: 1 2
