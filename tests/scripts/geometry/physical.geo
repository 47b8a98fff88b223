// Physical groups: explicit tags, names (auto tag = 1 + the largest physical tag of any
// dimension), += and -=, and Physical X{t} listing a group's entities.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(5) = {1, 2};
Physical Curve("top") = {3};
Physical Surface("sea") = {1};
Physical Point(3) = {1, 2};
Printf("%g", newreg);  // expect: 8
a[] = Physical Curve{5};
Printf("%g %g", #a[], a[1]);  // expect: 2 2
a[] = Physical Curve{6};
Printf("%g %g", #a[], a[0]);  // expect: 1 3
a[] = Physical Surface{7};
Printf("%g %g", #a[], a[0]);  // expect: 1 1
Physical Curve(5) += {4};
a[] = Physical Curve{5};
Printf("%g %g %g %g", #a[], a[0], a[1], a[2]);  // expect: 3 1 2 4
Physical Curve(5) -= {1};
a[] = Physical Curve{5};
Printf("%g %g %g", #a[], a[0], a[1]);  // expect: 2 2 4
Physical Curve("top") += {-4};
a[] = Physical Curve{6};
Printf("%g %g %g", #a[], a[0], a[1]);  // expect: 2 3 4
Physical Curve("side", 20) = {2};
Printf("%g", newreg);  // expect: 21
a[] = Physical Curve{20};
Printf("%g %g", #a[], a[0]);  // expect: 1 2
a[] = Physical Point{3};
Printf("%g %g %g", #a[], a[0], a[1]);  // expect: 2 1 2
a[] = Physical Curve{99};
Printf("%g", #a[]);  // expect: 0
Physical Curve(20) += {2, 3};
a[] = Physical Curve{20};
Printf("%g %g %g", #a[], a[0], a[1]);  // expect: 2 2 3
Printf(StrCat("names: ", Physical Curve{6}, "|", Physical Surface{7}, "|", Physical Curve{5}, "|", Physical Curve{42}));  // expect: names: top|sea||
Printf(StrCat(Physical Curve{20}, "!"));  // expect: side!
