// A MathEval syntax error is reported at its column inside the string literal.
Field[1] = MathEval;
Field[1].F = "x +* 2";
h = FieldValue(1, 0, 0, 0);
// expect error: 3:18: field-expression-error
