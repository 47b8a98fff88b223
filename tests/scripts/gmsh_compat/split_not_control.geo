// Split Curve at a point that is not one of the curve's control points: Gmsh skips that
// point (and splits at the others); so do we, with a warning.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0.2, 0, 0.5}; Point(3) = {2, 0, 0, 0.5};
Point(4) = {3, 0.3, 0, 0.5}; Point(5) = {0.5, 2, 0, 0.5};
Spline(1) = {1, 2, 3, 4};
Split Curve{1} Point{5, 3};
c[] = Curve{:};
Printf("%g %g", c[0], c[1]);  // expect: 2 3
p[] = PointsOf{Curve{c[0]};};
Printf("%g %g", p[0], p[1]);  // expect: 1 3
Spline(7) = {1, 5, 4};
Split Curve{7} Point{2};
c[] = Curve{:};
Printf("%g %g %g", #c[], c[0], c[2]);  // expect: 3 2 8
// expect warning: 6:1: gmsh-compat: curve 1 is not split at point 5, which is not one of its control points: Gmsh skips such a point, and so do we
// expect warning: 12:1: gmsh-compat: curve 7 is not split at point 2, which is not one of its control points: Gmsh skips such a point, and so do we
