l[] = {1:10:0};
// expect error:x the offending expression.
x = 1;
Printf("%g", x);  // expect: 1
y = x + undefined_var;
 :16: invalid-range
