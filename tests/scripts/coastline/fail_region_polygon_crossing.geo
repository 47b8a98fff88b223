// A Region polygon whose edges cross (a bow tie): an error at the Region statement.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "2000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/gb_ireland_f.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-6, 52, -4, 54, -4, 52, -6, 54};
// expect error: 11:23: wrong-coastline-option
