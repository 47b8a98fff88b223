// Coordinate belongs to Loops2 coastlines only.
Coastline[1] = GSHHS;
Coastline[1].Coordinate = "lonlat";
// expect error: 3:14: unknown-coastline-option
