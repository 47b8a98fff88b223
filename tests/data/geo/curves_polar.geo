// Gmsh 4.8.4 reference for tests/unit/geo/curve_gmsh_test.cpp: curves drawn in (u,v) on a
// PolarSphere (unit sphere at the origin) and on an off-centre PolarSphere of radius 2, plus
// one lon/lat Sphere. Regenerate with tests/data/geo/make_reference.sh.
Mesh.CharacteristicLengthFromCurvature = 0;
lc = 0.05;
Point(100) = {0, 0, 0, lc}; Point(101) = {0, 0, 1, lc};
PolarSphere(1) = {100, 101};
Point(1) = {0, 0, 0, lc};     Point(2) = {0.1, 0.1, 0, lc};  Point(3) = {0.2, -0.1, 0, lc};
Point(4) = {0.3, 0.05, 0, lc}; Point(5) = {0.4, 0.2, 0, lc}; Point(6) = {0.5, 0, 0, lc};
Point(7) = {-0.6, 0.9, 0, lc}; Point(8) = {-1.4, -0.3, 0, lc};
Line(1) = {1, 2};
Line(2) = {1:8};
Spline(3) = {1:8};
Spline(4) = {1:8, 1};
BSpline(5) = {1:8};                     // old uniform cubic, tripled end points
BSpline(6) = {1:8, 1};                  // old periodic uniform cubic
BSpline(7) = {1, 2, 3};
Bezier(8) = {1:6};
Euclidian Coordinates;
Point(200) = {1, 2, 3, lc}; Point(201) = {1, 2, 5, lc};
PolarSphere(2) = {200, 201};
Point(11) = {0.2, 0.3, 0, lc}; Point(12) = {-0.5, 0.8, 0, lc}; Point(13) = {-1.2, -0.2, 0, lc};
Point(14) = {0.1, -0.9, 0, lc}; Point(15) = {0.9, -0.3, 0, lc};
BSpline(9) = {11:15, 11};
Spline(10) = {11:15};
Euclidian Coordinates;
Point(300) = {0, 0, 0, lc}; Point(301) = {0, 0, 1, lc};
Sphere(3) = {300, 301};
Point(21) = {0.1, 0.2, 0, lc}; Point(22) = {0.5, 0.6, 0, lc}; Point(23) = {1.0, 0.3, 0, lc};
Point(24) = {1.4, -0.4, 0, lc}; Point(25) = {1.8, 0.1, 0, lc};
BSpline(11) = {21:25};
Line(12) = {21, 23};
