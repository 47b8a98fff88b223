// Statements the model has no place for yet are reported once per kind and
// skipped; the geometry and the variables go on.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
ReverseMesh Curve{1};
ReverseMesh Curve{1};
Coherence Point{1, 2};
Printf("%g", newp);  // expect: 3
// expect error: 6:1: not-supported-yet
// expect error: 8:1: not-supported-yet
