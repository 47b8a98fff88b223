// RegionalSea reads any shoreline format: RegionalFormat = "Shapefile" reads the GSHHS
// low-resolution level-1 shapefile of data/gshhs_shp (the whole world) cut to the
// Mediterranean box of examples/mediterranean.geo at 20 km, the Mediterranean kept.
// compare_with_gmsh: skip (native Coastline statements)
Include "earth.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(DataDir, "gshhs_shp/GSHHS_l_L1.shp");
RegionalFormat = "Shapefile";
RegionalBox[] = {RegionMediterranean[]};
RegionalAccuracy = 20e3;
RegionalSeaAt[] = {CentralMediterranean[]};
Call RegionalSea;
Printf("%g sea, open curves W %g E %g N %g", #RegionalSurfaces[], #Coastline{1, "OpenCurves", "West"},
       #Coastline{1, "OpenCurves", "East"}, #Coastline{1, "OpenCurves", "North"});
// expect: 1 sea, open curves W 1 E 2 N 4
