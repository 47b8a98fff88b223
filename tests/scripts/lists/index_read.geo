// An element read by a number, a variable or a constant index is read in place; any other
// index is evaluated first and may change the list, which is then read as it was before
// (src/interp/eval_expr.cpp, eval_index).
a[] = {1, 5, 7};
i = 2;
Printf("%g %g", a[i], a[0]);  // expect: 7 1
Printf("%g", a[a[0]++]);  // expect: 5
Printf("a", a[]);  // expect: a [0]2 [1]5 [2]7
s[] = Str("x", "y");
Printf("%s", s[i - 1]);  // expect: y
Printf("%s", s[i - 2]);  // expect: x
k = 0;
Printf("%s", s[k]);  // expect: x
// A loop reading the list element by element while it grows.
b[] = {};
For j In {0 : 2}
  b[] += a[j] * 10;
EndFor
Printf("b", b[]);  // expect: b [0]20 [1]50 [2]70
