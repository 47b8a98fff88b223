// No AccuracyField: the import says which option to set.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_c.txt";
loops[] = Coastline{1};
// expect error: 10:11: wrong-coastline-option
