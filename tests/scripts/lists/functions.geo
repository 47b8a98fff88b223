// List builtins.
a[] = LinSpace(0, 1, 5);
Printf("a", a[]);  // expect: a [0]0 [1]0.25 [2]0.5 [3]0.75 [4]1
b[] = LogSpace(0, 2, 3);
Printf("b", b[]);  // expect: b [0]1 [1]10 [2]100
c[] = List[a];
Printf("c", c[]);  // expect: c [0]0 [1]0.25 [2]0.5 [3]0.75 [4]1
d[] = List[{1, 2, 3}];
Printf("d", d[]);  // expect: d [0]1 [1]2 [2]3
Printf("%g", Find({1, 2, 3}, {2, 3, 4}));  // expect: 2
Printf("%g", Find({5}, {1, 2}));  // expect: 0
u[] = {3, 1, 2, 3, 1};
v[] = Unique(u[]);
Printf("v", v[]);  // expect: v [0]1 [1]2 [2]3
w[] = {-1, 2, -3};
x[] = Abs(w[]);
Printf("x", x[]);  // expect: x [0]1 [1]2 [2]3
