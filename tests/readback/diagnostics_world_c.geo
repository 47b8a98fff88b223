// GSHHG crude at 100 km with straits and narrow water closed: one Coastline{} that
// reports about a hundred changes (0.3 s), for the grouped diagnostics on stderr and
// --diagnostics FILE (diagnostics_json.py, tests/unit/cli/grouped_diagnostics_test.cpp).
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../data/gshhg/world_c.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].CloseStraits = 1;
Coastline[1].MinChannelWidth = 100e3;
loops[] = Coastline{1};
