// Importing a coastline that is not defined lists the defined ones.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
loops[] = Coastline{3};
// expect error: 9:21: missing-coastline
