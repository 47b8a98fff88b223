x = Sqrt(-1);
// expect error: 1:10: builtin-error
