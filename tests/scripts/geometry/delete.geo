// Delete and Recursive Delete: an entity used by a higher-dimensional one stays, and
// newp/newreg drop only when the largest tag goes.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {3, 3, 0};
Point(6) = {4, 3, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Delete { Point{6}; }
a[] = Point{:};
Printf("%g %g", #a[], newp);  // expect: 6 7
Delete { Curve{5}; }
a[] = Curve{:};
Printf("%g %g %g", #a[], newreg, newp);  // expect: 4 5 7
Delete { Point{5}; }
a[] = Point{:};
Printf("%g %g", #a[], newp);  // expect: 5 7
Delete { Surface{1}; }
a[] = Surface{:};
Printf("%g %g", #a[], newreg);  // expect: 0 5
