// Both For forms and Gmsh's loop-variable rules.
s = 0;
For i In {1:4}
  s += i;
EndFor
Printf("%g", s);
Printf("%g", i);
For j In {5:1}
  Printf("never");
EndFor
Printf("%g", j);
For k In {5:1:-2}
  Printf("k %g", k);
EndFor
Printf("%g", k);
For k In {1:2:0}
  Printf("z%g", k);
EndFor
Printf("%g", k);
c = 0;
For (1:3)
  c++;
EndFor
Printf("%g", c);
c = 0;
For (0:10:5)
  c += 1;
EndFor
Printf("%g", c);
c = 0;
For t In {0:1:0.1}
  c++;
EndFor
Printf("%g %g", c, t);
For i In {1:2}
  For j In {1:2}
    Printf("%g%g", i, j);
  EndFor
EndFor
n = 3;
For i In {1:n}
  n = 10;
EndFor
Printf("%g", i);
// gmsh 4.8.4 -0 output:
// expect: 10
// expect: 5
// expect: 5
// expect: k 5
// expect: k 3
// expect: k 1
// expect: -1
// expect: z1
// expect: 1
// expect: 3
// expect: 3
// expect: 11 1.1
// expect: 11
// expect: 12
// expect: 21
// expect: 22
// expect: 4
