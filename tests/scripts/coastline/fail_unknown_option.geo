// A misspelt option: the error suggests 'FileName'.
Coastline[1] = GSHHS;
Coastline[1].FileNme = "gshhs_c.b";
// expect error: 3:14: unknown-coastline-option
