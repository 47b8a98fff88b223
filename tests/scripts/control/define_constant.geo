// DefineConstant: first definition wins, ONELAB attributes are ignored.
DefineConstant[ a = 3, b = {4, Name "Parameters/b", Min 0, Max 10}, c ];
Printf("%g %g %g", a, b, c);  // expect: 3 4 0
DefineConstant[ a = 9 ];
Printf("%g", a);  // expect: 3
x = 1;
DefineConstant[ x = 2 ];
Printf("%g", x);  // expect: 1
DefineConstant[ s = "text" ];
Printf(s);  // expect: text
DefineConstant[ p = 1 q = 2 ];
Printf("%g %g", p, q);  // expect: 1 2
