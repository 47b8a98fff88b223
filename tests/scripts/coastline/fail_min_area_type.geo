// MinArea takes a number (km^2), not a string.
Coastline[1] = GSHHS;
Coastline[1].MinArea = "10";
// expect error: 3:24: wrong-coastline-option
