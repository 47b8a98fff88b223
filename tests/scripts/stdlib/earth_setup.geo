// stdlib/earth.geo (a different name from this file: Include looks here first) through the search path: constants, DataDir, the PolarSphere macro and
// the lon/lat conversions.
// compare_with_gmsh: skip (stdlib search path, native data paths)
Include "earth.geo";
Include "earth.geo";   // a second Include does nothing (no macro-redefined error)
Printf("%g %g %.6f", EarthRadius, Km, Deg2Rad * Rad2Deg);   // expect: 6.371e+06 1000 1.000000
Printf("%g", StrCmp(StrSub(GshhgDir, StrLen(GshhgDir) - 6), "gshhg/"));   // expect: 0
Call EarthSphere;
Printf("sphere %g", EarthSphereTag);   // expect: sphere 1
// Brest: back and forth.
lon = -4.49; lat = 48.39;
Call LonLatToXYZ;
Printf("%.3f", Hypot(x, Hypot(y, z)) / EarthRadius);   // expect: 1.000
lon = 0; lat = 0;
Call XYZToLonLat;
Printf("%.6f %.6f", lon, lat);   // expect: -4.490000 48.390000
// A point there is a model point on the sphere (3D coordinates back from Point{}).
Call LonLatPoint;
p[] = Point{LonLatPointTag};
Printf("%.0f %.0f %.0f", p[0] - x, p[1] - y, p[2] - z);   // expect: 0 0 0
// A quarter of the equator, and Brest-Reykjavik (2,042 km by the haversine formula in Python).
lon1 = 0; lat1 = 0; lon2 = 90; lat2 = 0;
Call GreatCircle;
Printf("%.1f", GreatCircleDistance / (Pi / 2 * EarthRadius));   // expect: 1.0
lon1 = -4.49; lat1 = 48.39; lon2 = -21.94; lat2 = 64.15;
Call GreatCircle;
Printf("%.0f km", GreatCircleDistance / Km);   // expect: 2042 km
// DataDir reaches the real data: a coastline file reads.
Field[1] = MathEval;
Field[1].F = "100e3";
Coastline[1] = LonLatText;
Coastline[1].FileName = StrCat(GshhgDir, "gb_ireland_f.txt");
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
Printf("%g loops", #loops[]);   // expect: 3 loops
