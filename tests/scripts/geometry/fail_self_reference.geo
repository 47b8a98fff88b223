// A Spline through the same point twice in a row (a zero-length piece). A Line from a
// point to itself is only a gmsh-compat warning (tests/scripts/gmsh_compat/line_to_itself.geo).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 3, 0};
Spline(1) = {1, 2, 2, 3};
// expect error: 6:1: self-reference
