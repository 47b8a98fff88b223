// Native extension: coastline import as curve loops.
Coastline[1] = GSHHS;
Coastline[1].FileName = "gshhs_c.b";
Coastline[1].Levels = {1};
Field[1] = MathEval;
Field[1].F = "5e4";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-12, 3, 48, 62};
Coastline[1].MinArea = 10;
loops[] = Coastline{1};
Plane Surface(1) = {loops[]};
Delete Coastline[1];
Plugin(GSHHS).iField = 1;
Plugin(GSHHS).Run;
