// Native behaviour (not Gmsh 4.8.4): C printf semantics for %d %i %x %c %s and
// "%%", and string arguments. compare_with_gmsh.sh skips this directory.
Printf("%d", 5);  // expect: 5
Printf("%5.3d|", 42.9);  // expect:   042|
Printf("%d %i", -3.7, 8);  // expect: -3 8
Printf("%x %X %o", 255, 255, 8);  // expect: ff FF 10
Printf("%c%c", 72, 105);  // expect: Hi
Printf("%s=%g", "v", 2);  // expect: v=2
Printf("[%-4s]", "ab");  // expect: [ab  ]
Printf("%g %%", 5);  // expect: 5 %
Printf("100%%");  // expect: 100%
name = "world";
Printf("hello %s", name);  // expect: hello world
s = Sprintf("%s-%d", "run", 3);
Printf(s);  // expect: run-3
// compare_with_gmsh: skip (native behaviour)
