// A runtime error stops the script at the offending expression.
x = 1;
Printf("%g", x);  // expect: 1
y = x + undefined_var;
Printf("never");
// expect error: 4:9: unknown-variable
