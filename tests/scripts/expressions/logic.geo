// Comparison, logic and the ternary operator.
Printf("%g", 3 > 2);  // expect: 1
Printf("%g", 3 < 2);  // expect: 0
Printf("%g", 3 >= 3);  // expect: 1
Printf("%g", 3 <= 2);  // expect: 0
Printf("%g", 2 == 2.0);  // expect: 1
Printf("%g", 3 != 3);  // expect: 0
Printf("%g", 1 && 0);  // expect: 0
Printf("%g", 1 && 2);  // expect: 1
Printf("%g", 0 || 0);  // expect: 0
Printf("%g", 0 || 5);  // expect: 1
Printf("%g", !0);  // expect: 1
Printf("%g", !7);  // expect: 0
Printf("%g", 1 ? 2 : 3);  // expect: 2
Printf("%g", 0 ? 2 : 3);  // expect: 3
Printf("%g", 1 < 2 ? 10 : 20);  // expect: 10
Printf("%g", 0 ? 1 : 0 ? 2 : 3);  // expect: 3
Printf("%g", 1 + 1 == 2 && 2 > 1);  // expect: 1
x = 5;
Printf("%g", x > 3 && x < 10);  // expect: 1
