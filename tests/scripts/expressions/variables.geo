// Assignment operators, ++/--, name suffixes and Exists.
x = 3;
x += 2;
Printf("%g", x);
x -= 1;
Printf("%g", x);
x *= 3;
Printf("%g", x);
x /= 4;
Printf("%g", x);
x++;
Printf("%g", x);
x--;
x--;
Printf("%g", x);
a = 5;
b = a++;
Printf("%g %g", a, b);
For i In {1:3}
  v~{i} = i * 10;
EndFor
Printf("%g %g %g", v_1, v_2, v~{3});
w~{2}~{5} = 7;
Printf("%g", w_2_5);
Printf("%g", v~{2.7});
Printf("%g", Exists(x));
Printf("%g", Exists(nothere));
Printf("%g", Exists(v~{1}));
StringToName["named"] = 42;
Printf("%g", named);
Printf("%g", S2N["named"] + 1);
Delete x;
Printf("%g", Exists(x));
// gmsh 4.8.4 -0 output:
// expect: 5
// expect: 4
// expect: 12
// expect: 3
// expect: 4
// expect: 2
// expect: 6 5
// expect: 10 20 30
// expect: 7
// expect: 20
// expect: 1
// expect: 0
// expect: 1
// expect: 42
// expect: 43
// expect: 0
