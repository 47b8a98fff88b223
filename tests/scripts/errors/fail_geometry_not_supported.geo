// Geometry statements are reported once per kind and skipped; variables go on.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Field[1] = Distance;
Printf("%g", newp);  // expect: 1
// expect error: 2:1: not-supported-yet
// expect error: 4:1: not-supported-yet
// expect error: 5:1: not-supported-yet
