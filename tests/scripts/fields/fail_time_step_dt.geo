// TimeStep needs a positive Dt: the error points at the assignment.
Field[1] = MathEval;
Field[1].F = "100";
Field[2] = TimeStep;
Field[2].DepthField = 1;
Field[2].Dt = 0;
h = FieldValue(2, 0, 0, 0);
// expect error: 6:1: bad-field-value
