// Native extension: Assert(condition, "message", args...).
n = 4;
Assert(n == 4, "n is %g", n);
Assert(n > 0);
Printf("ok");  // expect: ok
// compare_with_gmsh: skip (native behaviour)
