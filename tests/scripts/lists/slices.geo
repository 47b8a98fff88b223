// Sub-lists, lists in arithmetic and lengths.
l[] = {0, 10, 20, 30, 40, 50};
a[] = l[{1:3}];
Printf("a", a[]);  // expect: a [0]10 [1]20 [2]30
b[] = l({0, 5});
Printf("b", b[]);  // expect: b [0]0 [1]50
c[] = l[{5:0:-2}];
Printf("c", c[]);  // expect: c [0]50 [1]30 [2]10
Printf("%g", #l());  // expect: 6
d[] = 3*{1, 2} ;
Printf("d", d[]);  // expect: d [0]3 [1]6
e[] = {l[0], l[#l[]-1]};
Printf("e", e[]);  // expect: e [0]0 [1]50
g[] = {1, 2};
g[] += g[];
Printf("g", g[]);  // expect: g [0]1 [1]2 [2]1 [3]2
h[] = LinSpace(1, 2, 3);
h[] -= {1.5};
Printf("h", h[]);  // expect: h [0]1 [1]2
i[] = {5:5};
Printf("i", i[]);  // expect: i [0]5
