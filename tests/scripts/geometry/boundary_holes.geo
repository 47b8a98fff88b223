// Boundary{} of plane surfaces with a hole: holes are listed reversed, against the outer
// loop, and the sign of the surface tag does not matter (as gmsh 4.8.4 prints them).
Point(1) = {0,0,0}; Point(2) = {4,0,0}; Point(3) = {4,4,0}; Point(4) = {0,4,0};
Point(5) = {1,1,0}; Point(6) = {2,1,0}; Point(7) = {2,2,0}; Point(8) = {1,2,0};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Line(5) = {5,6}; Line(6) = {6,7}; Line(7) = {7,8}; Line(8) = {8,5};
Curve Loop(1) = {1,2,3,4}; Curve Loop(2) = {5,6,7,8};
Plane Surface(1) = {1, 2};
b[] = Boundary{Surface{1};}; Printf("%g %g %g %g %g %g %g %g", b[]);
Plane Surface(2) = {-1, -2};
b[] = Boundary{Surface{2};}; Printf("%g %g %g %g %g %g %g %g", b[]);
b[] = Boundary{Surface{-1};}; Printf("%g %g %g %g %g %g %g %g", b[]);
b[] = CombinedBoundary{Surface{1};}; Printf("%g %g %g %g %g %g %g %g", b[]);
// gmsh 4.8.4 -0 output:
// expect: 1 2 3 4 -8 -7 -6 -5
// expect: -4 -3 -2 -1 5 6 7 8
// expect: 1 2 3 4 -8 -7 -6 -5
// expect: 1 2 3 4 -5 -6 -7 -8
