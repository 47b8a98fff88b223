// An AccuracyField naming a field that does not exist: reported at that option when the
// import builds it.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[2] = LonLatText;
Coastline[2].FileName = "../../../data/gshhg/world_c.txt";
Coastline[2].AccuracyField = 5;
loops[] = Coastline{2};
// expect error: 11:1: missing-field
