// Deleting a coastline that is not there.
Coastline[1] = LonLatText;
Delete Coastline[4];
// expect error: 3:18: missing-coastline
