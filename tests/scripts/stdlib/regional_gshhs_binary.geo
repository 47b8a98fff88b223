// RegionalSea reads any shoreline format: RegionalFormat = "gshhs" (any case) reads a GSHHS
// binary, here the full-resolution Great Britain and Ireland cut of data/gshhs, with the
// Irish Sea polygon of regional_polygon.geo: one sea and the same 2 open curves, St
// George's Channel (edge 9, from the last vertex to the first) and the North Channel
// (edge 5).
// compare_with_gmsh: skip (native Coastline statements)
Include "earth.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(DataDir, "gshhs/gshhs_f_gb_ireland_generated.b");
RegionalFormat = "gshhs";
RegionalBox[] = {-5.27, 51.89, -2.2, 52.2, -2.2, 55.3, -4.5, 55.1, -5.0, 54.90,
                 -6.10, 55.17, -7.5, 54.5, -7.5, 52.5, -6.45, 52.22};
RegionalAccuracy = 2e3;
RegionalSeaAt[] = {-5.4, 53.35};
Call RegionalSea;
Printf("%g sea, %g open curves, %g along edge 9, %g along edge 5", #RegionalSurfaces[], #RegionalOpenCurves[],
       #Coastline{1, "OpenCurves", "Edge9"}, #Coastline{1, "OpenCurves", "Edge5"});
// expect: 1 sea, 2 open curves, 1 along edge 9, 1 along edge 5
