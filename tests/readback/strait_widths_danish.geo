// The Danish straits (Øresund, Great Belt, Little Belt) from the system's GSHHG at full
// resolution, gamma 350 m in the straits and 3 km away from them, the coast held within
// DeviationFactor x gamma of the data (docs/coastlines.md, "The curve within a bound of
// the data"). strait_widths.py meshes it at DeviationFactor 0 and 0.5 and measures each
// strait's width across fixed sections in the mesh and in the source shoreline.
// OutDir and Deviation are set by the test.
DefineConstant[ OutDir = ".", Deviation = 0.5, StraitSize = 350, FarSize = 3e3 ];
Include "earth.geo";
Call EarthSphere;

// Points along the three straits: the size is StraitSize within 8 km of them (both banks
// of every section of strait_widths.py), FarSize from 30 km on.
StraitPoints[] = {12.62, 56.04,  12.68, 55.92,  12.72, 55.80,     // Øresund, north half
                  11.02, 55.34,  10.88, 55.33,  10.97, 55.44,     // Great Belt at the bridge
                  11.04, 55.24,
                  9.74, 55.50,   9.68, 55.56,   9.82, 55.46};     // Little Belt at Middelfart
near[] = {};
For i In {0 : #StraitPoints[] - 1 : 2}
  lon = StraitPoints[i];  lat = StraitPoints[i + 1];
  Call LonLatPoint;
  near[] += LonLatPointTag;
EndFor
Field[1] = Distance;
Field[1].PointsList = {near[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = StraitSize;
Field[2].SizeMax = FarSize;
Field[2].DistMin = 8e3;
Field[2].DistMax = 30e3;

Coastline[1] = GSHHG;
Coastline[1].Resolution = "f";
Coastline[1].AccuracyField = 2;           // gamma: the mesh size itself
Coastline[1].DeviationFactor = Deviation;
Coastline[1].Region = {9.5, 13.2, 54.3, 56.3};
Coastline[1].SeaAt = {11.8, 56.2};        // the Kattegat
sea[] = Coastline{1, "Surfaces"};
Physical Surface("sea") = {sea[]};
Physical Curve("coast") = {Coastline{1, "CoastCurves"}};
Physical Curve("open") = {Coastline{1, "OpenCurves"}};
d[] = Coastline{1, "Deviation"};
Printf("deviation: max %g m, 95%% %g m, max before %g m, %g points put back", d[0], d[1], d[2], d[5]);

Background Field = 2;
Mesh 2;
Save StrCat(OutDir, "/danish_straits.msh");
