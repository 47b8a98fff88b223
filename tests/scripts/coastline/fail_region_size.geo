// Region takes four numbers.
Coastline[1] = GSHHS;
Coastline[1].Region = {-12, 3, 48};
// expect error: 3:23: wrong-coastline-option
