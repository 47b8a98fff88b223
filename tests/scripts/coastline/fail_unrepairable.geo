// Two islands whose outlines overlap in the source data so that their union encloses a
// lagoon (tests/data/coast_scripts/lagoon_loops2.txt, west of Portugal): no repair applies,
// and the error names both records and the place.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "1000";
Coastline[1] = Loops2;
Coastline[1].FileName = "../../data/coast_scripts/lagoon_loops2.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-21, -19, 39, 41};
loops[] = Coastline{1};
// expect error: 14:11: coastline-error
