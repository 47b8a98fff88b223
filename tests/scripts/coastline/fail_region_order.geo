// Region is {west, east, south, north}: west > east is refused where it is written.
Coastline[1] = GSHHS;
Coastline[1].Region = {3, -12, 48, 62};
// expect error: 3:23: wrong-coastline-option
