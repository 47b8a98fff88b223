// FieldValue of a field that does not exist.
Field[1] = Box;
h = FieldValue(2, 0, 0, 0);
// expect error: 3:5: missing-field
