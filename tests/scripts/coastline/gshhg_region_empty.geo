// A Region holding no shoreline (the South Pacific between Pitcairn and Easter Island):
// a note at the Region, and its box is the only loop, one open-boundary curve.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
Coastline[1] = GSHHG;
Coastline[1].Resolution = "l";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-125, -115, -40, -30};
loops[] = Coastline{1};
open[] = Coastline{1, "OpenCurves"};
coast[] = Coastline{1, "CoastCurves"};
Printf("loops %g, open curves %g, coast curves %g", #loops[], #open[], #coast[]);
// expect: loops 1, open curves 1, coast curves 0
