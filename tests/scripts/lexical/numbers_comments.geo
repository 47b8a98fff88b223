// Numbers, comments and whitespace (Gmsh 4.8.4 lexical rules).
a = 123;
Printf("%g", a);  // expect: 123
b = 1.;
Printf("%g", b);  // expect: 1
c = .5;
Printf("%g", c);  // expect: 0.5
d = 1.5e-3;
Printf("%g", d);  // expect: 0.0015
e = 2E4;
Printf("%g", e);  // expect: 20000
/* a block comment
   over two lines */ f = 7;
Printf("%g", f);  // expect: 7
g = 3; // trailing comment
Printf("%g", g);  // expect: 3
h =
  4
  ;
Printf("%g", h);  // expect: 4
Pointer = 5;
Printf("%g", Pointer);  // expect: 5
_x1 = 6;
Printf("%g", _x1);  // expect: 6
Printf("%g", 1e300*10 > 1e300);  // expect: 1
Printf("%.17g", 0.1);  // expect: 0.10000000000000001
