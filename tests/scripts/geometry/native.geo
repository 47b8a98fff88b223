// compare_with_gmsh: skip
// Native forms gmsh 4.8.4 does not parse: #Curve{:} counts, Assert on the model,
// `Coordinates Surface g;`, the `Euclidean` spelling, a string variable naming a
// physical group, and the model-checking Asserts the world test relies on.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
Point(3) = {0.1, 0.1, 0};
Point(4) = {-0.1, 0.1, 0};
Point(5) = {0, -0.1, 0};
BSpline(1) = {3, 4, 5, 3};
Curve Loop(1) = {1};
Euclidean Coordinates;
Point(6) = {0.1, 0.1, 0};
Coordinates Surface 1;
Point(7) = {0.5, 0, 0};
Assert(#Point{:} == 7, "7 points, got %g", #Point{:});
Assert(#Curve{:} == 1 && #Surface{:} == 0, "one curve, no surface");
p[] = Point{6};
Assert(p[2] == 0, "point 6 is Euclidean");
p[] = Point{7};
Assert(Fabs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1) < 1e-15, "point 7 is on the unit sphere");
Plane Surface(1) = {1};
name = "coast";
Physical Curve(name) = {1};
Physical Curve(name) += {1, 1};
Assert(#Physical Curve{1} == 1, "+= does not add a member twice (gmsh 4.8.4)");
b[] = Boundary{ Curve{1}; };
Assert(b[0] == 3 && b[1] == 3, "a closed BSpline starts and ends at its first point");
Printf("%g %g %g", #Point{:}, #Curve{:}, #Surface{:});  // expect: 7 1 1
