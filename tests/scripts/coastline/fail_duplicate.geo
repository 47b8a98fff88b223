// A coastline defined twice: 'Delete Coastline[1];' first (the first definition is a note).
Coastline[1] = LonLatText;
Coastline[1] = GSHHS;
// expect error: 3:11: duplicate-coastline
