// RegionalSea passes RegionalKeepOpen[] to Coastline.KeepOpen: the Mediterranean at 5 km
// with RegionalMinChannelWidth = 2 km, the Bosporus and the Dardanelles kept open, so that
// the Black Sea comes with the kept sea (open curves on the East and North sides of the box,
// as in tests/scripts/coastline/mediterranean_keep_open.geo); without it they close.
// compare_with_gmsh: skip (native Coastline statements)
Include "earth.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(GshhgDir, "world_i_A100.txt");
RegionalBox[] = {-5.6, 37, 29, 46.5};
RegionalAccuracy = 5e3;
RegionalMinChannelWidth = 2e3;
RegionalSeaAt[] = {18, 35};
RegionalKeepOpen[] = {29.08, 41.12, 26.40, 40.20};   // the Bosporus and the Dardanelles (in their water)
Call RegionalSea;
Printf("%g sea, open curves E %g N %g, %g closures", #RegionalSurfaces[], #Coastline{1, "OpenCurves", "East"},
       #Coastline{1, "OpenCurves", "North"}, #Coastline{1, "Closures"} / 3);
// expect: 1 sea, open curves E 2 N 4, 20 closures
