// Circle{start, centre, end}: the end is much further from the centre than the start.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 3, 0};
Circle(1) = {2, 1, 3};
// expect error: 5:1: not-cocircular
