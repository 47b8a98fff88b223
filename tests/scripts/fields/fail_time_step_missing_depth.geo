// A TimeStep whose DepthField names no field: reported where it is used, with a note
// at the option that names it.
Field[2] = TimeStep;
Field[2].DepthField = 7;
Field[2].Dt = 30;
h = FieldValue(2, 0, 0, 0);
// expect error: 6:5: missing-field
