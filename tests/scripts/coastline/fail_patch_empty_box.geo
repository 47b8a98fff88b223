// A patch whose box holds none of its shoreline (the Scheldt banks, a box off Calais):
// an error at the Patch statement, before any meshing.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_i_A100.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {2, 6, 50.5, 52.5};
Coastline[1].Patch = "../../../data/osm/scheldt_osm.txt";
Coastline[1].PatchBox = {2.0, 2.5, 50.9, 51.2};
loops[] = Coastline{1};
// expect error: 13:1: coastline-error
