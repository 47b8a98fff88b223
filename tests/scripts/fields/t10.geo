// Gmsh tutorial t10's field set (Distance, Threshold, MathEval, Box, Min),
// checked at a few points against values computed by hand from the formulas
// of docs/fields.md (Distance samples: 98 points per curve; F5 adds
// Sprintf("%g", lc/10) = 0.015).
lc = .15;
Point(1) = {0.0, 0.0, 0, lc};
Point(2) = {1, 0.0, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Point(5) = {0.2, .5, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(5) = {1, 2, 3, 4};
Plane Surface(6) = {5};
Field[1] = Distance;
Field[1].PointsList = {5};
Field[1].CurvesList = {2};
Field[1].NumPointsPerCurve = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc / 30;
Field[2].SizeMax = lc;
Field[2].DistMin = 0.15;
Field[2].DistMax = 0.5;
Field[3] = MathEval;
Field[3].F = "Cos(4*3.14*x) * Sin(4*3.14*y) / 10 + 0.101";
Field[4] = Distance;
Field[4].CurvesList = {1};
Field[4].NumPointsPerCurve = 100;
Field[5] = MathEval;
Field[5].F = Sprintf("F4^3 + %g", lc / 10);
Field[6] = Box;
Field[6].VIn = lc / 15;
Field[6].VOut = lc;
Field[6].XMin = 0.3;
Field[6].XMax = 0.6;
Field[6].YMin = 0.3;
Field[6].YMax = 0.6;
Field[6].Thickness = 0.3;
Field[7] = Min;
Field[7].FieldsList = {2, 3, 5, 6};
Background Field = 7;

// At Point 5: F2 = SizeMin = lc/30, F5 = 0.500004^3 + 0.015, F6 = lc/15 + (0.1/0.3)(lc - lc/15).
Printf("%.6g %g", FieldValue(7, 0.2, 0.5, 0), FieldArgmin(7, 0.2, 0.5, 0));     // expect: 0.005 2
Printf("%.6g", FieldValue(3, 0.2, 0.5, 0));                                      // expect: 0.101257
Printf("%.6g", FieldValue(6, 0.2, 0.5, 0));                                      // expect: 0.0566667
Printf("%.6g", FieldValue(5, 0.2, 0.5, 0));                                      // expect: 0.140003
// Inside the box: F6 = VIn = lc/15.
Printf("%.6g %g", FieldValue(7, 0.45, 0.45, 0), FieldArgmin(7, 0.45, 0.45, 0));  // expect: 0.01 6
Printf("%.6g", FieldValue(2, 0.45, 0.45, 0));                                    // expect: 0.0484797
// Near Curve 1: F5 = F4^3 + 0.015 wins.
Printf("%.6g %g", FieldValue(7, 0.8, 0.2, 0), FieldArgmin(7, 0.8, 0.2, 0));      // expect: 0.0230012 5
Printf("%.6g %g", FieldValue(7, 0.05, 0.05, 0), FieldArgmin(7, 0.05, 0.05, 0));  // expect: 0.015125 5
// Where the cosine dips: F3.
Printf("%.6g %g", FieldValue(7, 0.1, 0.9, 0), FieldArgmin(7, 0.1, 0.9, 0));      // expect: 0.0714987 3
Printf("%.6g", FieldValue(2, 0.1, 0.9, 0));                                      // expect: 0.113672
// Near Curve 2 (x = 1): F2 = SizeMin.
Printf("%.6g %g", FieldValue(7, 0.95, 0.6, 0), FieldArgmin(7, 0.95, 0.6, 0));    // expect: 0.005 2
