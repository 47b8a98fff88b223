// A reference to a field that does not exist.
Field[1] = Threshold;
Field[1].InField = 5;
Field[2] = Min;
Field[2].FieldsList = {1};
h = FieldValue(2, 0, 0, 0);
// expect error: 6:5: missing-field
