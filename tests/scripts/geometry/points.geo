// Point{t} coordinates: plain points, Geometry.ScalingFactor, and points given by
// their (u, v) on a PolarSphere (Gmsh's stereographic map) and on a lon/lat Sphere.
Point(1) = {0.5, -2, 3.25, 0.1};
p[] = Point{1};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 0.5 -2 3.25
Geometry.ScalingFactor = 2;
Point(2) = {1, 2, 3};
p[] = Point{2};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 2 4 6
Geometry.ScalingFactor = 1;
Point(3) = {0, 0, 0};
Point(4) = {0, 0, 1};
PolarSphere(1) = {3, 4};
Point(5) = {-0.3, -0.3, 0};
Point(6) = {0, 0, 0};
Point(7) = {1, 0, 0};
Point(8) = {2.5, -1.5, 7};
p[] = Point{5};
Printf("%.5f %.5f %.5f", p[0], p[1], p[2]);  // expect: 0.50847 0.50847 0.69492
p[] = Point{6};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 0 0 1
p[] = Point{7};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: -1 0 0
p[] = Point{8};
Printf("%.12g %.12g %.12g", p[0], p[1], p[2]);  // expect: -0.526315789474 0.315789473684 -0.789473684211
Euclidian Coordinates;
Point(9) = {-0.3, -0.3, 0};
p[] = Point{9};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: -0.3 -0.3 0
Point(10) = {1, 2, 3};
Point(11) = {1, 2, 5};
PolarSphere(2) = {10, 11};
Point(12) = {0.25, 0.5, 0};
p[] = Point{12};
Printf("%.12g %.12g %.12g", p[0], p[1], p[2]);  // expect: 0.238095238095 0.47619047619 4.04761904762
Euclidian Coordinates;
Point(13) = {0, 0, 0};
Point(14) = {0, 0, 6371};
Sphere(3) = {13, 14};
Point(15) = {0.5, 0.25, 0};
p[] = Point{15};
Printf("%.6g %.6g %.6g", p[0], p[1], p[2]);  // expect: 5417.27 2959.47 1576.21
a[] = Point{:};
Printf("%g points, newp %g", #a[], newp);  // expect: 15 points, newp 16
