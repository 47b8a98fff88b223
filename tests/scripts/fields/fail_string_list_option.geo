// A string option takes one string, not a list of them.
Field[1] = MathEval;
Field[1].F = Str("x", "y");
// expect error: 3:14: wrong-field-option-type: option 'F' of Field[1] takes one string, not a list of 2
