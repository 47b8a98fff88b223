// Native: `Coordinates Surface g;` makes an existing sphere current again and
// `Euclidean Coordinates;` leaves it (gmsh 4.8.4 accepts only 'Euclidian' and has no
// 'Coordinates Surface'); an unknown geometry is an error.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 2};
PolarSphere(1) = {1, 2};
Euclidean Coordinates;
Point(3) = {0.5, 0.5, 0};
p[] = Point{3};
Printf("%g %g %g", p[0], p[1], p[2]);  // expect: 0.5 0.5 0
Coordinates Surface 1;
Point(4) = {0.5, 0.5, 0};
p[] = Point{4};
Printf("%.6f %.6f %.6f", p[0], p[1], p[2]);  // expect: -1.333333 -1.333333 0.666667
Coordinates Surface 9;
// expect error: 15:1: missing-entity
