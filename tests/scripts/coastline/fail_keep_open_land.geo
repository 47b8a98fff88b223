// A KeepOpen point on land (in Sicily): an error at the statement that set it.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_i_A100.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-5.6, 37, 29, 46.5};
Coastline[1].MinChannelWidth = 2000;
Coastline[1].KeepOpen = {29.08, 41.12, 14, 37.5};
loops[] = Coastline{1};
// expect error: 13:1: coastline-error
