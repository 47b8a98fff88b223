// String builtins, checked against gmsh 4.8.4.
s = StrCat("a", "b", "c");
Printf(s);
s = Str("line1", "line2");
Printf(s);
s = StrCat("n", Sprintf("%g", 3));
Printf(s);
s = Sprintf("v=%g w=%g", 1.5, 2);
Printf(s);
s = Sprintf("plain");
Printf(s);
Printf("%g", StrLen("hello"));
Printf("%g", StrCmp("a", "b"));
Printf("%g", StrCmp("b", "a"));
Printf("%g", StrCmp("a", "a"));
Printf("%g", StrFind("hello", "ll"));
Printf("%g", StrFind("hello", "z"));
s = StrSub("hello", 1, 3);
Printf(s);
s = StrSub("hello", 2);
Printf(s);
s = StrPrefix("dir/file.geo");
Printf(s);
s = StrRelative("dir/file.geo");
Printf(s);
s = StrReplace("aXbXc", "X", "--");
Printf(s);
s = UpperCase("abc");
Printf(s);
s = StrChoice(1, "yes", "no");
Printf(s);
s = StrChoice(0, "yes", "no");
Printf(s);
s = DirName("/a/b/c.geo");
Printf(s);
x = 5;
s = NameToString[x];
Printf(s);
s = N2S[x];
Printf(s);
Printf("%g", FileExists("functions.geo"));
Printf("%g", FileExists("no_such_file.geo"));
t[] = Str("p", "q");
Printf("%g", #t[]);
u = StrCat(t[1], t[0]);
Printf(u);
// gmsh 4.8.4 -0 output:
// expect: abc
// expect: line1
// expect: line2
// expect: n3
// expect: v=1.5 w=2
// expect: plain
// expect: 5
// expect: -1
// expect: 1
// expect: 0
// expect: 1
// expect: 0
// expect: ell
// expect: llo
// expect: dir/file
// expect: file.geo
// expect: a--b--c
// expect: ABC
// expect: yes
// expect: no
// expect: /a/b/
// expect: x
// expect: x
// expect: 1
// expect: 0
// expect: 2
// expect: qp
