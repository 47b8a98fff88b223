// A Region polygon wholly on land (in Wales): an error at the import.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "2000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/gb_ireland_f.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-3.8, 52.0, -3.2, 52.0, -3.5, 52.4};
loops[] = Coastline{1};
// expect error: 11:1: coastline-error
