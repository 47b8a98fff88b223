// Sizes must be positive: reported at the statement that set the bad value.
Field[1] = MathEval;
Field[1].F = "x";
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = -0.1;
h = FieldValue(2, 1, 0, 0);
// expect error: 6:1: bad-field-value: Field[2] (Threshold): option 'SizeMin': a size must be positive and finite
