// Operators and precedence, checked against gmsh 4.8.4.
Printf("%g", 1 + 2 * 3);  // expect: 7
Printf("%g", (1 + 2) * 3);  // expect: 9
Printf("%g", 7 - 2 - 1);  // expect: 4
Printf("%g", 8 / 2 / 2);  // expect: 2
Printf("%g", 5 / 2);  // expect: 2.5
Printf("%g", -2^2);  // expect: -4
Printf("%g", 2^3^2);  // expect: 512
Printf("%g", 2^-1);  // expect: 0.5
Printf("%g", 1 + 2 * 3^2);  // expect: 19
Printf("%g", 7 % 3);  // expect: 1
Printf("%g", -7 % 3);  // expect: -1
Printf("%g", 7.9 % 3);  // expect: 1
Printf("%g", 6 | 1);  // expect: 7
Printf("%g", 6 & 3);  // expect: 2
Printf("%g", 2 | 1 * 4);  // expect: 12
Printf("%g", 1 << 3);  // expect: 8
Printf("%g", 16 >> 2);  // expect: 4
Printf("%g", -3 + +3);  // expect: 0
Printf("%g", 10 - -2);  // expect: 12
Printf("%g", 1/3);  // expect: 0.333333
Printf("%.10f", 2/3);  // expect: 0.6666666667
Printf("%g", 1e-3 * 1e3);  // expect: 1
Printf("%g", 0.1 + 0.2 == 0.3);  // expect: 0
