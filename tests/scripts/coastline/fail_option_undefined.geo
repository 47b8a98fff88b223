// An option of a coastline that is not defined.
Coastline[1] = GSHHS;
Coastline[2].FileName = "gshhs_c.b";
// expect error: 3:11: missing-coastline
