j = 0;
Printf("%g", nolist[j]);
// expect error: 2:14: unknown-variable
