// A file with syntax errors is not run at all: every syntax error is listed.
Printf("not printed");
x = (1 + ;
y = 2
z = 3;
// expect error: 3:10: expected-expression
// expect error: 4:6: expected-semicolon
