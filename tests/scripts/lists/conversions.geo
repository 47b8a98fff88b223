// Scalar/list conversions and string lists.
a[] = {1, 2};
b = a[];
Printf("b", b[]);  // expect: b [0]1 [1]2
Printf("%g", #b[]);  // expect: 2
c = {};
Printf("%g", #c[]);  // expect: 0
d[] = {4};
Printf("%g", d);  // expect: 4
e = 5;
e[] += {6, 7};
Printf("e", e[]);  // expect: e [0]5 [1]6 [2]7
s[] = Str("a");
s[] += Str("b", "c");
Printf("%g", #s[]);  // expect: 3
t = StrCat(s[2], s[0]);
Printf(t);  // expect: ca
If (a[1] == 2)
  Printf("second is two");  // expect: second is two
EndIf
f[] = {a[], a[]};
Printf("f", f[]);  // expect: f [0]1 [1]2 [2]1 [3]2
g[] = 2 * a[];
Printf("g", g[]);  // expect: g [0]2 [1]4
h[] = {};
h[2] = 1;
Printf("h", h[]);  // expect: h [0]0 [1]0 [2]1
