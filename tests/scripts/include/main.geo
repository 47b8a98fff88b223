// Include: relative to the including file; macros from included files stay callable.
base = 1;
Include "sub/part.inc";
Printf("%g", part);
Call FromPart;
Printf("%g", base);
Include "sub/part.inc";
Printf("%g", part);
// gmsh 4.8.4 -0 output:
// expect: deeper 1
// expect: 10
// expect: 6
// expect: deeper 2
// expect: 11
