// MaxDeviation is a distance in metres: zero or negative is refused where it is written.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
Coastline[1] = GSHHG;
Coastline[1].Resolution = "c";
Coastline[1].AccuracyField = 1;
Coastline[1].MaxDeviation = 0;
// expect error: 11:29: wrong-coastline-option
