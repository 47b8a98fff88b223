// Too many curve samples for one build (a hostile NumPointsPerCurve).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Field[1] = Distance;
Field[1].CurvesList = {1};
Field[1].NumPointsPerCurve = 6e7;
h = FieldValue(1, 0, 0, 0);
// expect error: 7:1: bad-field-value: NumPointsPerCurve: more than 50000000 curve samples in one build
