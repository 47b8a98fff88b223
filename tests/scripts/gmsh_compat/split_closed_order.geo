// Split Curve on a closed curve: Gmsh starts the pieces at the first listed point met after
// the curve's start point, in the curve's order, whatever the order of the list
// (benchmarks/2d_large/mediterranean.geo relies on which piece gets which tag).
For i In {0:7}
  Point(1 + i) = {Cos(i * Pi / 4), Sin(i * Pi / 4), 0, 0.5};
EndFor
BSpline(1) = {1:8, 1};
Split Curve{1} Point{1, 4};
For c In {2:3}
  p[] = PointsOf{Curve{c};};
  Printf("%g: %g %g", c, p[0], p[1]);
EndFor
BSpline(4) = {1:8, 1};
Split Curve{4} Point{7, 3};
For c In {5:6}
  p[] = PointsOf{Curve{c};};
  Printf("%g: %g %g", c, p[0], p[1]);
EndFor
// gmsh 4.8.4 -0 output:
// expect: 2: 4 1
// expect: 3: 1 4
// expect: 5: 3 7
// expect: 6: 7 3
