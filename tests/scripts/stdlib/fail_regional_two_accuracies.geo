// RegionalSea takes the coastline's gamma as a constant or as a field, not both: setting
// RegionalAccuracy and RegionalAccuracyField is an error located at the macro's check
// (line 92 of stdlib/regions.geo).
// compare_with_gmsh: skip (stdlib search path)
Include "earth.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(GshhgDir, "gb_ireland_f.txt");
RegionalBox[] = {-7, -2.5, 51.5, 55.5};
RegionalAccuracy = 2e3;
gamma_ = newf;
Field[gamma_] = MathEval;
Field[gamma_].F = "2e3";
RegionalAccuracyField = gamma_;
Call RegionalSea;
// expect error: 92:7: user-error
