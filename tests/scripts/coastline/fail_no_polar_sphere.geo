// The import needs a current PolarSphere to put its points on: none is defined here.
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_c.txt";
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
// expect error: 7:11: coastline-error
