// A Plane Surface whose enclosing loop is listed after its hole: Gmsh meshes the region
// between them whatever their order; we take the enclosing loop as the outer one and warn.
Point(1) = {0, 0, 0, 0.3}; Point(2) = {3, 0, 0, 0.3}; Point(3) = {3, 3, 0, 0.3}; Point(4) = {0, 3, 0, 0.3};
Point(5) = {1, 1, 0, 0.3}; Point(6) = {2, 1, 0, 0.3}; Point(7) = {2, 2, 0, 0.3}; Point(8) = {1, 2, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Curve Loop(3) = {-8, -7, -6, -5};
Plane Surface(1) = {2, 1};
Plane Surface(2) = {3};
// Boundary keeps the script's order: the first listed loop as is, the others reversed.
b[] = Boundary{Surface{1};};
Printf("%g", #b[]);
For i In {0:#b[] - 1}
  Printf("%g", b[i]);
EndFor
s[] = Surface{:};
Printf("%g %g", s[0], s[1]);
// expect warning: 10:1: gmsh-compat: plane surface 1: curve loop 1 encloses the others but is listed after curve loop 2; Gmsh finds the enclosing loop, and so do we: curve loop 1 is the outer one
// gmsh 4.8.4 -0 output:
// expect: 8
// expect: 5
// expect: 6
// expect: 7
// expect: 8
// expect: -4
// expect: -3
// expect: -2
// expect: -1
// expect: 1 2
