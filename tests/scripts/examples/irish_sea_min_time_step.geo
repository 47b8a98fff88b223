// Mesh.MinTimeStep on the tutorial's Irish Sea (examples/irish_sea.geo) with no
// MinChannelWidth: the depth field comes first, so that the coastline's import closes the
// passages too narrow for a 10 s step at their depth; the mesh reaches 10 s. The Cymyran
// Strait between Holy Island and Anglesey pinches to 30.6 m in GSHHG full (4.560W
// 53.256N, tests/scripts/coastline/holy_island_strait.geo). With the curve within gamma / 2
// of the data (the default DeviationFactor 0.5) the source points at the pinch are control
// points, so the import sees its real width: at the 5 m the depth field gives there (its
// MinDepth) one element across would cost 4.4 s, and a 10 s step closes it (with the
// coarse curve it saw 137 m there, 19.5 s, and left it open).
// compare_with_gmsh: skip (native Coastline and Field statements)
DefineConstant[ CoastSize = 2e3, FarSize = 15e3, Reach = 100e3 ];
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";
Call EarthSphere;
BathyFile = StrCat(BathyDir, "etopo5_nw_europe_5min.nc");
Depth = newf;
Field[Depth] = Bathymetry;
Field[Depth].FileName = BathyFile;
Field[Depth].Output = "depth";
Field[Depth].MinDepth = 5;
Mesh.DepthField = Depth;
Mesh.MinTimeStep = 10;
RegionalFile = StrCat(GshhgDir, "gb_ireland_f.txt");
RegionalBox[] = {-7, -2.5, 51.5, 55.5};
RegionalAccuracy = CoastSize;
RegionalSeaAt[] = {-5.4, 53.35};
Call RegionalSea;
ShoreSizeMin = CoastSize;  ShoreSizeMax = FarSize;  ShoreDistMax = Reach;
ShorePoints[] = RegionalShorePoints[];  ShoreBox[] = RegionalBox[];
Call ShoreProximity;
TidalPointsPerWaveLength = 150;  TidalSizeMin = CoastSize;  TidalSizeMax = FarSize;
Call TidalWavelength;
OceanFields[] = {ShoreField, TidalField};
Call OceanSize;
cl[] = Coastline{1, "Closures"};   // RegionalSea imports Coastline[1]
For i In {0 : #cl[] - 1 : 3}
  If (Fabs(cl[i] + 4.560) < 0.01 && Fabs(cl[i + 1] - 53.256) < 0.01)
    Printf("Cymyran Strait closed: width %.1f m", cl[i + 2]);
  EndIf
EndFor
// expect: Cymyran Strait closed: width 30.5 m
Mesh 2;
Printf("time step at least 10 s: %g", Mesh.StatsTimeStep >= 10);
// expect: time step at least 10 s: 1
