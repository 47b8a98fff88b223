// RegionalSea's RegionalFormat must name a shoreline format of `Coastline[n] = ...;`: an
// unknown one is an error located at the macro's check (line 121 of stdlib/regions.geo).
// compare_with_gmsh: skip (stdlib search path)
Include "earth.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(GshhgDir, "gb_ireland_f.txt");
RegionalFormat = "GeoJSON";
RegionalBox[] = {-7, -2.5, 51.5, 55.5};
Call RegionalSea;
// expect error: 121:9: user-error
