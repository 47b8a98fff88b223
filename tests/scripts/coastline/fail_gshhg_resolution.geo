// Resolution takes GMT's letters, crude to full: anything else is refused where it is set.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Coastline[1] = GSHHG;
Coastline[1].Resolution = "x";
// expect error: 7:27: wrong-coastline-option
