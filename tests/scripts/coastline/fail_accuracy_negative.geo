// gamma(x) must be positive: a field that is negative south of the equator is refused with
// the place where it was evaluated.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "z";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_c.txt";
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
// expect error: 12:11: coastline-error
