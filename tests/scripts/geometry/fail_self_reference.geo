// A line from a point to itself.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 3, 0};
Line(1) = {2, 2};
// expect error: 5:1: self-reference
