// stdlib/ocean_fields.geo's physical criteria on ETOPO5 5' around the Great Barrier Reef:
// the tidal wavelength T sqrt(g H) / N refines the shallow shelf, the paper's f1 the abyss;
// the slope criterion (2 pi / N) H / |grad H| is positive and clamped.
// compare_with_gmsh: skip (stdlib search path, native fields)
Include "ocean_fields.geo";
Call EarthSphere;
BathyFile = StrCat(BathyDir, "etopo5_gbr_5min.nc");
Call TidalWavelength;
Call WaveLength;
Call BathySlope;
depth = newf;
Field[depth] = Bathymetry;
Field[depth].FileName = BathyFile;
// 150E 15S, 1856 m deep: 44712 sqrt(9.81 1856) / 50 = 120,664.0 m.
lon = 150; lat = -15; Call LonLatToXYZ;
Printf("%.1f", FieldValue(TidalCriterionField, x, y, z));   // expect: 120664.0
deep_tidal = FieldValue(TidalField, x, y, z);
deep_wave = FieldValue(WaveField, x, y, z);
deep_h = FieldValue(depth, x, y, z);
// On the shelf off Cairns (146E 16.5S), about 19 m deep.
lon = 146; lat = -16.5; Call LonLatToXYZ;
shelf_h = FieldValue(depth, x, y, z);
Printf("shelf shallower: %g", shelf_h < 100 && deep_h > 1000);   // expect: shelf shallower: 1
Printf("tidal finer on the shelf: %g", FieldValue(TidalField, x, y, z) < deep_tidal);   // expect: tidal finer on the shelf: 1
Printf("f1 finer in the abyss: %g", FieldValue(WaveField, x, y, z) > deep_wave);   // expect: f1 finer in the abyss: 1
s = FieldValue(SlopeField, x, y, z);
Printf("slope clamped: %g", s >= SlopeSizeMin && s <= SlopeSizeMax);   // expect: slope clamped: 1
