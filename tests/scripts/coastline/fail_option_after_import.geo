// Options cannot change once the coastline is imported (its entities already exist); a
// second Coastline{1} returns the same loops without importing again.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
Coastline[1] = Loops2;
Coastline[1].FileName = "../../data/coast_scripts/islands_loops2.txt";
Coastline[1].AccuracyField = 1;
a[] = Coastline{1};
b[] = Coastline{1};
Printf("same loops: %g", #a[] == 3 && #b[] == 3 && a[0] == b[0] && a[2] == b[2]);
Coastline[1].MinArea = 10;
// expect: same loops: 1
// expect warning: 12:7: coastline-repair
// expect warning: 12:7: coastline-repair
// expect error: 15:1: wrong-coastline-option
