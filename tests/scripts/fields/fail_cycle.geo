// Fields that reference each other: the cycle is reported at the use, with
// a note at each option statement of the loop.
Field[1] = Min;
Field[2] = Threshold;
Field[3] = MathEval;
Field[1].FieldsList = {2, 3};
Field[2].InField = 3;
Field[3].F = "F1 + 1";
h = FieldValue(1, 0, 0, 0);
// expect error: 9:5: field-cycle
