// Patch names a file (a Path row of coast/coastline_options.def, as FileName and
// RegionFile): an empty name is refused where it is written.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_i_A100.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Patch = "";
// expect error: 12:22: wrong-coastline-option
