Printf("%g", 1, 2);
// expect error: 1:17: format-error
