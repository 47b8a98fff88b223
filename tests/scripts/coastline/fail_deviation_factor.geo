// DeviationFactor is a fraction of gamma, 0 to measure only: negative is refused.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
Coastline[1] = GSHHG;
Coastline[1].Resolution = "c";
Coastline[1].AccuracyField = 1;
Coastline[1].DeviationFactor = -0.5;
// expect error: 11:32: wrong-coastline-option
