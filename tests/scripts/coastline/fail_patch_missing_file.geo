// A patch file that does not exist: an error at the Patch statement.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_i_A100.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {2, 6, 50.5, 52.5};
Coastline[1].Patch = "no_such_patch.txt";
Coastline[1].PatchBox = {3.52, 4.44, 51.21, 51.46};
loops[] = Coastline{1};
// expect error: 12:1: wrong-coastline-option
