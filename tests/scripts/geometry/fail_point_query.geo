// Point{t} of a point that does not exist is an error that names the point.
Point(1) = {0, 0, 0};
p[] = Point{1};
q[] = Point{7};
// expect error: 4:7: missing-entity
