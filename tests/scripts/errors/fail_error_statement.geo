// Error() reports and the script goes on (as in Gmsh); the run fails.
Error("bad value %g", 2);
Printf("after");  // expect: after
// expect error: 2:1: user-error
