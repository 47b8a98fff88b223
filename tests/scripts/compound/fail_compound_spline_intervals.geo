// A negative number of intervals (Gmsh: "Negative number of intervals in compound spline").
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Compound Spline(2) = {1} Using -2;
// expect error: 5:32: invalid-operation
