// A data file that does not exist: reported at the option that names it
// when the field is built (here by FieldValue), with the use as a note.
Field[1] = Bathymetry;
Field[1].FileName = "no_such_grid.nc";
h = FieldValue(1, 1, 0, 0);
// expect error: 4:1: field-file-error
