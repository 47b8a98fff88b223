Printf("%g %g", 1);
// expect error: 1:1: format-error
