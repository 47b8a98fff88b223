// Physical tags are a high-water mark: an emptied group, -= and Delete Physicals leave newreg
// and the next automatic tag where they were (gmsh 4.8.4).
Point(1) = {0,0,0}; Point(2) = {1,0,0}; Line(1) = {1,2};
Physical Curve(5) = {1};
Printf("%g", newreg);  // expect: 6
Delete { Curve{1}; }
a[] = Physical Curve{5};
Printf("%g %g", newreg, #a[]);  // expect: 6 0
Line(1) = {1,2};
Physical Curve(9) = {1};
Physical Curve(9) -= {1};
Printf("%g", newreg);  // expect: 10
Delete Physicals;
Printf("%g", newreg);  // expect: 10
Physical Curve("x") = {1};
a[] = Physical Curve{10};
Printf("%g %g", newreg, #a[]);  // expect: 11 1
