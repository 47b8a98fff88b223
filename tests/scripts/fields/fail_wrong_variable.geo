// A netCDF variable the file does not have.
Field[1] = Bathymetry;
Field[1].FileName = "../../../data/bathymetry/etopo5_gbr_5min.nc";
Field[1].ZVariable = "depth";
h = FieldValue(1, 1, 0, 0);
// expect error: 3:1: field-file-error
