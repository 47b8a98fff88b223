s = StrSub("abc", 5);
// expect error: 1:19: builtin-error
