// Resolution is an option of the GSHHG source only.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Coastline[1] = LonLatText;
Coastline[1].Resolution = "c";
// expect error: 7:14: unknown-coastline-option
