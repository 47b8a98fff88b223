// A curve through a point that does not exist.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Spline(2) = {2, 3, 1};
// expect error: 5:1: missing-entity
