// Macro/Function, Call by name and by string, globals shared.
Macro Double
  v = v * 2;
Return
v = 3;
Call Double;
Printf("%g", v);
Call "Double";
Printf("%g", v);
Function Inc
  v += 1;
  inside = 1;
Return
Call Inc;
Printf("%g %g", v, inside);
name = "Inc";
Call Str(name);
Printf("%g", v);
Macro Loop
  For m In {1:3}
    total += m;
  EndFor
Return
total = 0;
Call Loop;
Call Loop;
Printf("%g", total);
Macro Outer
  Call Double;
  v += 100;
Return
v = 1;
Call Outer;
Printf("%g", v);
// gmsh 4.8.4 -0 output:
// expect: 6
// expect: 12
// expect: 13 1
// expect: 14
// expect: 12
// expect: 102
