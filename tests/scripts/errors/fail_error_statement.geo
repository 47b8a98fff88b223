// Error() reports and the script goes on (as in Gmsh); the run fails.
Error("bad value %g", 2);
Printf("after");  // expect: after
// expect error: 2:1: user-error: bad value 2
// The script's text is the message as it is, braces and all.
Warning("{} and {{x}} stay as written");
// expect warning: 6:1: user-warning: {} and {{x}} stay as written
