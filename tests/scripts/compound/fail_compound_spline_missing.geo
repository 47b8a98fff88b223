// A compound spline through a curve that does not exist.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Compound BSpline(2) = {1, 7} Using 3;
// expect error: 5:23: missing-entity
