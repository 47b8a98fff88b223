// String literals: single or double quotes, no escape processing.
s = "double";
Printf(s);  // expect: double
t = 'single';
Printf(t);  // expect: single
u = "it's";
Printf(u);  // expect: it's
v = 'say "hi"';
Printf(v);  // expect: say "hi"
w = "back\nslash";
Printf(w);  // expect: back\nslash
Printf("%g", StrLen("a\tb"));  // expect: 4
