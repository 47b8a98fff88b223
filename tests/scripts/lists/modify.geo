// Appending, removing, element and sub-list assignment.
l[] = {1, 2, 3};
l[] += {4, 5};
Printf("l", l[]);  // expect: l [0]1 [1]2 [2]3 [3]4 [4]5
l[] -= {2, 5};
Printf("l", l[]);  // expect: l [0]1 [1]3 [2]4
l[] += 6;
Printf("l", l[]);  // expect: l [0]1 [1]3 [2]4 [3]6
y[] = {1, 2, 2, 3};
y[] -= 2;
Printf("y", y[]);  // expect: y [0]1 [1]2 [2]3
y += 7;
Printf("y", y[]);  // expect: y [0]1 [1]2 [2]3 [3]7
t = 3;
t[] += {4};
Printf("t", t[]);  // expect: t [0]3 [1]4
m[3] = 1;
Printf("m", m[]);  // expect: m [0]0 [1]0 [2]0 [3]1
m[1] += 5;
Printf("m", m[]);  // expect: m [0]0 [1]5 [2]0 [3]1
m(0) = 9;
Printf("m", m[]);  // expect: m [0]9 [1]5 [2]0 [3]1
s[] = l[{0, 1}];
Printf("s", s[]);  // expect: s [0]1 [1]3
l[{0, 2}] = {100, 300};
Printf("l", l[]);  // expect: l [0]100 [1]3 [2]300 [3]6
l[{0, 1}] += {1, 1};
Printf("l", l[]);  // expect: l [0]101 [1]4 [2]300 [3]6
q[] = {};
q[] += {1};
Printf("q", q[]);  // expect: q [0]1
new[] += {8, 9};
Printf("new", new[]);  // expect: new [0]8 [1]9
