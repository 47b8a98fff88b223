// A MathEval syntax error is reported at the option that set the expression.
Field[1] = MathEval;
Field[1].F = "x +* 2";
h = FieldValue(1, 0, 0, 0);
// expect error: 3:1: field-expression-error
