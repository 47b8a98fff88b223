// Coherence merges points closer than Geometry.Tolerance times the model size (the
// lowest tag survives) and then identical curves.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0, 0};
Point(4) = {1, 1, 0};
Line(1) = {1, 2};
Line(2) = {3, 4};
Coherence;
a[] = Point{:};
Printf("%g %g %g", #a[], a[0], a[1]);  // expect: 3 1 2
b[] = Boundary{ Curve{2}; };
Printf("%g %g", b[0], b[1]);  // expect: 2 4
Point(5) = {0, 0, 1e-12};
Line(3) = {5, 2};
Coherence;
a[] = Point{:};
c[] = Curve{:};
Printf("%g %g", #a[], #c[]);  // expect: 3 2
Point(6) = {0.5, 0.5, 0.001};
Point(7) = {0.5, 0.5, 0};
Coherence;
a[] = Point{:};
Printf("%g", #a[]);  // expect: 5
Geometry.Tolerance = 1e-3;
Coherence;
a[] = Point{:};
Printf("%g %g", #a[], a[#a[] - 1]);  // expect: 4 6
