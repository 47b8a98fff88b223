// Lists: creation, indexing with [] and (), length, ranges, scalar-as-list.
l[] = {1, 2, 3};
Printf("l", l[]);  // expect: l [0]1 [1]2 [2]3
Printf("%g", #l[]);  // expect: 3
Printf("%g", l[1]);  // expect: 2
Printf("%g", l(2));  // expect: 3
Printf("%g", l);  // expect: 1
m = {4, 5, 6};
Printf("m", m[]);  // expect: m [0]4 [1]5 [2]6
n = {7};
Printf("n", n[]);  // expect: n [0]7
e[] = {};
Printf("%g", #e[]);  // expect: 0
r[] = {1:5};
Printf("r", r[]);  // expect: r [0]1 [1]2 [2]3 [3]4 [4]5
r2[] = {1:10:3, 20};
Printf("r2", r2[]);  // expect: r2 [0]1 [1]4 [2]7 [3]10 [4]20
r3[] = {5:1};
Printf("r3", r3[]);  // expect: r3 [0]5 [1]4 [2]3 [3]2 [4]1
r4[] = {5:1:-2};
Printf("r4", r4[]);  // expect: r4 [0]5 [1]3 [2]1
r5[] = {0:1:0.25};
Printf("r5", r5[]);  // expect: r5 [0]0 [1]0.25 [2]0.5 [3]0.75 [4]1
r6[] = {0:0.3:0.1};
Printf("r6", r6[]);  // expect: r6 [0]0 [1]0.1 [2]0.2
r7[] = {1.5:4};
Printf("r7", r7[]);  // expect: r7 [0]1.5 [1]2.5 [2]3.5
Printf("r", 1:10:3);  // expect: r [0]1 [1]4 [2]7 [3]10
neg[] = -{1, 2};
Printf("neg", neg[]);  // expect: neg [0]-1 [1]-2
sc[] = 2*{1, 2};
Printf("sc", sc[]);  // expect: sc [0]2 [1]4
s = 3;
Printf("s", s[]);  // expect: s [0]3
Printf("%g", #s[]);  // expect: 1
nested[] = {l[], 10, 11:12};
Printf("nested", nested[]);  // expect: nested [0]1 [1]2 [2]3 [3]10 [4]11 [5]12
