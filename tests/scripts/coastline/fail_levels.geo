// GSHHS levels run from 1 to 6.
Coastline[1] = GSHHS;
Coastline[1].Levels = {1, 7};
// expect error: 3:23: wrong-coastline-option
