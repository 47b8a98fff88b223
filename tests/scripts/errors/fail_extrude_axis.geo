// A rotation about an axis of zero length is an error at the Extrude.
Point(1) = {1, 0, 0, 0.1};
Extrude {{0, 0, 0}, {0, 0, 0}, Pi/2} { Point{1}; }
// expect error: 3:1: invalid-operation
