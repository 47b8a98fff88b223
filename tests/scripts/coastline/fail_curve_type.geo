// CurveType is "BSpline" or "Line".
Coastline[1] = GSHHS;
Coastline[1].CurveType = "Spline";
// expect error: 3:26: wrong-coastline-option
