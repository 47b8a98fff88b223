// Where Gmsh's line-based re-reading differs, statements run in order here.
Macro SetV
  v = 2;
Return
v = 1; Call SetV; Printf("v=%g", v);  // expect: v=2
c = 0;
For i In {1:3} c += i; EndFor Printf("%g %g", c, i);  // expect: 6 4
// Only the chosen branch of ?: is evaluated (Gmsh evaluates both).
x = 1 ? 2 : undefined_name;
Printf("%g", x);  // expect: 2
// Step() is in the documentation but not in 4.8.4's parser.
Printf("%g %g", Step(-1), Step(3));  // expect: 0 1
// Nested braces flatten.
l[] = {1, {2, 3}, {}};
Printf("l", l[]);  // expect: l [0]1 [1]2 [2]3
// compare_with_gmsh: skip (native behaviour)
