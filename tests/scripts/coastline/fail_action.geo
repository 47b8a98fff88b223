// Coastlines have no actions: the error says how to import.
Coastline[1] = GSHHS;
Coastline[1].Import;
// expect error: 3:14: unknown-coastline-option
