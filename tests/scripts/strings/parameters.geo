// ONELAB-style parameters (SetNumber, GetNumber, DefineConstant with Name) and
// DefineNumber, as Gmsh 4.8.4 runs them in batch mode.
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
DefineConstant[ b = {4, Name "Parameters/b"} ];
Printf("%g", GetNumber("Parameters/b"));  // expect: 4
DefineConstant[ s2 = {"hello", Name "Parameters/s"} ];
t = GetString("Parameters/s");
Printf(t);  // expect: hello
SetNumber("Parameters/b", 8);
DefineConstant[ c = {5, Name "Parameters/b"} ];
Printf("%g", c);  // expect: 8
