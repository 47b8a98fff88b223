// `Compound BSpline(t) = {curves} Using n;` and `Compound Spline`: Gmsh 4.8.4 samples
// n - 1 new points on each curve at equal steps of its parameter (new point tags, in
// order) and makes a B-spline (a spline) through the first curve's begin point, those
// points and each curve's end point. Printf lines checked against `gmsh -0` by hand.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 2, 0, 0.3};
Line(1) = {1, 2};
Line(2) = {2, 3};
Compound BSpline(3) = {1, 2} Using 4;
Printf("%g", newp);   // expect: 10
p[] = Point{5};
Printf("%g %g %g", p[0], p[1], p[2]);   // expect: 0.5 0 0
p[] = Point{8};
Printf("%g %g %g", p[0], p[1], p[2]);   // expect: 1 1 0
b[] = Boundary{Curve{3};};
Printf("%g %g", b[0], b[1]);   // expect: 1 3
// A reversed curve is sampled from its end.
Compound Spline(4) = {-2} Using 2;
p[] = Point{10};
Printf("%g %g %g", p[0], p[1], p[2]);   // expect: 1 1 0
b[] = Boundary{Curve{4};};
Printf("%g %g", b[0], b[1]);   // expect: 3 2
Printf("%g", newl);   // expect: 5
