// An edge beyond the Region polygon's count: an error at the selector, before any import.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "2000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/gb_ireland_f.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-5.27, 51.89, -2.2, 52.2, -2.2, 55.3, -4.5, 55.1, -5.0, 54.90,
                       -6.10, 55.17, -7.5, 54.5, -7.5, 52.5, -6.45, 52.22};
west[] = Coastline{1, "OpenCurves", "Edge10"};
// expect error: 13:20: wrong-coastline-option
