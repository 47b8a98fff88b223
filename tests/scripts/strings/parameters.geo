// ONELAB-style parameters and DefineNumber, as Gmsh 4.8.4 runs them in batch mode.
SetNumber("qq", 9);
Printf("%g", GetNumber("qq"));  // expect: 9
Printf("%g", GetNumber("nope", 3));  // expect: 3
x = DefineNumber(5, Name "x");
Printf("%g", x);  // expect: 5
f = CurrentFileName;
Printf(f);  // expect: parameters.geo
t = Today;
Printf("%g", StrLen(t) > 10);  // expect: 1
Printf("%g", Cpu >= 0);  // expect: 1
s = "str";
Printf("%g", Exists(s));  // expect: 1
