// Rotate needs {axis, point, angle}.
Point(1) = {1, 0, 0};
Rotate{{0, 0, 1}, Pi / 2}{ Point{1}; }
// expect error: 3:1: list-size-mismatch
