// A point swept by more than Pi would be a circle arc of more than Pi, which the built-in
// kernel does not hold: an error at the Extrude (split the rotation in two).
Point(1) = {1, 0, 0, 0.1};
Extrude {{0, 0, 1}, {0, 0, 0}, 3*Pi/2} { Point{1}; }
// expect error: 4:1: invalid-geometry
