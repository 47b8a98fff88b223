// Boundary{} and CombinedBoundary{} of curves and surfaces: two unit squares that
// share curve 2, with one of them written through reversed curves.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0};
Point(6) = {2, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {2, 5};
Line(6) = {5, 6};
Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-7, -6, -5, 2};
Plane Surface(2) = {2};
b[] = Boundary{ Curve{1}; };
Printf("%g %g", b[0], b[1]);  // expect: 1 2
b[] = Boundary{ Curve{-3}; };
Printf("%g %g", b[0], b[1]);  // expect: 4 3
b[] = Boundary{ Surface{1}; };
Printf("%g %g %g %g", b[0], b[1], b[2], b[3]);  // expect: 1 2 3 4
b[] = Boundary{ Surface{2}; };
Printf("%g %g %g %g", b[0], b[1], b[2], b[3]);  // expect: -7 -6 -5 2
b[] = CombinedBoundary{ Surface{1, 2}; };
Printf("%g", #b[]);  // expect: 6
Printf("%g %g %g %g %g %g", b[0], b[1], b[2], b[3], b[4], b[5]);  // expect: 1 3 4 -5 -6 -7
b[] = CombinedBoundary{ Curve{1, 5}; };
Printf("%g %g %g", #b[], b[0], b[1]);  // expect: 2 1 5
b[] = Boundary{ Surface{1}; Curve{6}; };
Printf("%g", #b[]);  // expect: 6
c[] = Curve{:};
Printf("%g %g", #c[], c[6]);  // expect: 7 7
s[] = Surface{:};
Printf("%g %g %g", #s[], s[0], s[1]);  // expect: 2 1 2
s[] = Surface In BoundingBox{-0.1, -0.1, -0.1, 1.1, 1.1, 0.1};
Printf("%g %g", #s[], s[0]);  // expect: 1 1
s[] = Surface In BoundingBox{-0.1, -0.1, -0.1, 2.1, 1.1, 0.1};
Printf("%g %g %g", #s[], s[0], s[1]);  // expect: 2 1 2
c[] = Curve In BoundingBox{0.9, -0.1, -0.1, 2.1, 1.1, 0.1};
Printf("%g %g %g %g %g", #c[], c[0], c[1], c[2], c[3]);  // expect: 4 2 5 6 7
