// Deleting a curve that a surface still uses leaves it there with a warning (Gmsh skips
// it silently); deleting an unknown entity is an error.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Delete { Curve{2}; }
c[] = Curve{:};
Printf("%g", #c[]);  // expect: 3
Delete { Point{42}; }
// expect warning: 11:1: delete-skipped
// expect error: 14:1: missing-entity
