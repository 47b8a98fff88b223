// Gmsh 4.8.4 reference for tests/unit/geo/curve_gmsh_test.cpp: Euclidean curves of every kind.
// Regenerate with tests/data/geo/make_reference.sh (gmsh -1, MSH 4.1, Mesh.SaveParametric=1).
Mesh.CharacteristicLengthFromCurvature = 0;
lc = 0.07;
Point(1) = {0, 0, 0, lc};   Point(2) = {1, 1, 0, lc};     Point(3) = {2, -1, 0.5, lc};
Point(4) = {3, 0.5, 0, lc}; Point(5) = {4, 2, 0, lc};     Point(6) = {5, 0, 1, lc};
Point(7) = {5.5, 1.5, 0.2, lc}; Point(8) = {6.5, 1, -0.3, lc};
Line(1) = {1, 2};                       // segment
Line(2) = {1:6};                        // polyline
Spline(3) = {1:8};                      // Catmull-Rom, phantom end points
Spline(4) = {1:6, 1};                   // periodic Catmull-Rom
BSpline(5) = {1:8};                     // clamped cubic
BSpline(6) = {1:6, 1};                  // periodic uniform cubic
BSpline(7) = {1, 2};                    // degree 1
BSpline(8) = {1, 2, 3};                 // degree 2
BSpline(9) = {1, 2, 3, 4};              // cubic Bezier
BSpline(10) = {1, 2, 2, 3, 4, 5, 5, 6}; // repeated control points
Bezier(11) = {1:6};                     // degree 5
Point(20) = {0, 0, 0, lc}; Point(21) = {1, 0, 0, lc}; Point(22) = {0, 1, 0, lc};
Point(23) = {-1, 0.2, 0.3, lc}; Point(24) = {-1, 0, 0, lc};
Circle(12) = {21, 20, 22};              // quarter circle
Circle(13) = {22, 20, 23};              // end point off the start radius (Gmsh keeps R1)
Circle(14) = {21, 20, 24};              // half circle, default normal
Circle(15) = {24, 20, 22} Plane{0, 0, 1};
Point(30) = {2, 0, 0, lc}; Point(31) = {0, 0.5, 0, lc}; Point(32) = {0.3, 0.8, 0.1, lc};
Ellipse(16) = {30, 20, 31};             // 3 points: start is on the major axis
Ellipse(17) = {31, 20, 30, 23};         // major axis point, end out of the start plane
Ellipse(18) = {32, 20, 30, 23};
Point(40) = {10, 10, 10, lc}; Point(41) = {12, 11, 9, lc}; Point(42) = {9, 12, 11.5, lc};
Circle(19) = {41, 40, 42};              // off-origin centre, oblique plane
