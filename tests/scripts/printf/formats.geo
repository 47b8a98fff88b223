// Printf formatting rules of gmsh 4.8.4.
Printf("a %g b", 5);  // expect: a 5 b
Printf("%5.2f|%e|%10g|%-6g|", 3.14159, 2.5, 7, 8);  // expect:  3.14|2.500000e+00|         7|8     |
Printf("x=%g y=%g", 1.5, 2);  // expect: x=1.5 y=2
Printf("%g", 1e20);  // expect: 1e+20
Printf("%g %g", 1:2);  // expect: 1 2
Printf("%03.0f", 7);  // expect: 007
Printf("%.3g|%G|%E|%5.1e", 3.14159, 1e-10, 12345.678, 0.000123);  // expect: 3.14|1E-10|1.234568E+04|1.2e-04
Printf("%g|%g", -0.0, 1/3);  // expect: -0|0.333333
Printf("%.0f %.0f", 0.5, 1.5);  // expect: 0 2
Printf("%g %g", 1e-5, 123456789);  // expect: 1e-05 1.23457e+08
Printf("%+g % g", 3, 3);  // expect: +3  3
Printf("%lf", 2.5);  // expect: 2.500000
Printf("a%gb%gc", 1, 2);  // expect: a1b2c
L[] = {1, 2, 3};
Printf("L", L[]);  // expect: L [0]1 [1]2 [2]3
Printf("nothing");  // expect: nothing
x = 3;
Printf("x", x);  // expect: x [0]3
Printf("%g %g %g", L[]);  // expect: 1 2 3
Printf("%g-%g", L[{0, 2}]);  // expect: 1-3
Printf("sum %g", L[0] + L[1] + L[2]);  // expect: sum 6
Printf(StrCat("built", " format %g"), 9);  // expect: built format 9
