// Periodic Surface must pair every curve of the target's boundary (as Gmsh's
// setMeshMaster, which finds no counterpart for curve 8 otherwise): the list is refused
// at its place.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {3, 0, 0}; Point(6) = {4, 0, 0}; Point(7) = {4, 1, 0}; Point(8) = {3, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Periodic Surface 2 {5, 6, 7} = 1 {1, 2, 3};
// expect error: 10:20: invalid-operation
