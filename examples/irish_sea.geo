// The tutorial's model (docs/tutorial.md): the Irish Sea, from nothing to a mesh an ocean
// model runs. This file is the tutorial's geo blocks in their order; tests/tutorial/
// run_tutorial.py (CTest `tutorial`) checks that the two stay the same.
//   stereomesh -0 examples/irish_sea.geo                 (evaluate and check)
//   stereomesh -2 examples/irish_sea.geo -o irish_sea.14 (ADCIRC fort.14 with depths)
// The Irish Sea: 2 km on the coasts to 15 km at 100 km from them (docs/tutorial.md).
DefineConstant[ CoastSize = 2e3, FarSize = 15e3, Reach = 100e3 ];
Include "earth.geo";          // found in stdlib/ through the search path
Include "ocean_fields.geo";
Include "regions.geo";
Call EarthSphere;

RegionalFile = StrCat(GshhgDir, "gb_ireland_f.txt");   // GSHHG full resolution
RegionalBox[] = {-7, -2.5, 51.5, 55.5};                 // W, E, S, N in degrees
RegionalAccuracy = CoastSize;          // gamma: one control point about every 2 km
RegionalMinChannelWidth = CoastSize;   // close passages narrower than that
RegionalSeaAt[] = {-5.4, 53.35};       // keep the sea holding this point
Call RegionalSea;
Printf("%g sea, %g coast curves, %g open-boundary curves",
       #RegionalSurfaces[], #RegionalCoastCurves[], #RegionalOpenCurves[]);

ShoreSizeMin = CoastSize;          // on the coast
ShoreSizeMax = FarSize;            // at ShoreDistMax from it, and beyond
ShoreDistMax = Reach;
ShorePoints[] = RegionalShorePoints[];
ShoreBox[] = RegionalBox[];        // the box's sides are sea, not coast
Call ShoreProximity;

// The tide: T sqrt(g H) / N (T the M2 period), finer where the water is shallow.
BathyFile = StrCat(BathyDir, "etopo5_nw_europe_5min.nc");
TidalPointsPerWaveLength = 150;
TidalSizeMin = CoastSize;
TidalSizeMax = FarSize;
Call TidalWavelength;

OceanFields[] = {ShoreField, TidalField};
Call OceanSize;                    // the Min of the criteria -> Background Field

lon = -5.4;  lat = 53.35;                      // mid-channel, Dublin-Holyhead
Call LonLatToXYZ;
h = FieldValue(SizeField, x, y, z);
Printf("mid-channel: %.1f km, set by the %s", h / Km,
       FieldArgmin(MinSizeField, x, y, z) == ShoreField ? "shore" : "tide");
lon = -3.6;  lat = 53.6;                       // Liverpool Bay
Call LonLatToXYZ;
Printf("Liverpool Bay: %.1f km, set by the %s", FieldValue(SizeField, x, y, z) / Km,
       FieldArgmin(MinSizeField, x, y, z) == ShoreField ? "shore" : "tide");
Assert(h >= CoastSize && h <= FarSize, "mid-channel size %g m", h);

Depth = newf;
Field[Depth] = Bathymetry;
Field[Depth].FileName = BathyFile;
Field[Depth].Output = "depth";     // metres, positive down
Field[Depth].MinDepth = 5;         // the shallowest water the model runs
Mesh.DepthField = Depth;
