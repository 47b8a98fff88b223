// A wrong number of coordinates in Point.
Point(1) = {0, 0};
// expect error: 2:12: list-size-mismatch
