// A binned GSHHG file that is not there: the error, at the FileName statement, names the
// Debian package that installs that resolution (here the full one, gmt-gshhg-full).
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = GSHHG;
Coastline[1].FileName = "no_such_dir/binned_GSHHS_f.nc";
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
// expect error: 10:1: coastline-error
