// Coastline{n, "What"} returns Loops, Curves, OpenCurves, Points, ControlPoints, Outer or
// LoopsPerSurface.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_c.txt";
Coastline[1].AccuracyField = 1;
x[] = Coastline{1, "Islands"};
// expect error: 12:20: unknown-coastline-option
