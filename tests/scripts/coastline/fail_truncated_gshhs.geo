// The first 3,000 bytes of gshhs_c.b: the record cut in the middle is named, nothing is
// imported.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = GSHHS;
Coastline[1].FileName = "../../data/coast_scripts/truncated_gshhs_c.b";
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
// expect error: 10:1: coastline-error
