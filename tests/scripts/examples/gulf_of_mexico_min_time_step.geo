// examples/gulf_of_mexico.geo with Mesh.MinTimeStep = 10 s: its depth field moved before
// the import (the closures need the depth), the rest as shipped. As shipped the step is
// 1.3 s, set by the 66 m mouth of a bay on Cuba's north coast (77.47W 21.78N, 258 m
// deep). Here the passages too narrow for 10 s at their depth are closed (the 97 m one at
// 80.61W 28.41N, a 6.3 s step, checked below), but that bay's mouth is not: the mesh's
// step is still 1.31 s there after three nodes are removed (known gap, see the commit
// message of this file).
// compare_with_gmsh: skip (native Coastline and Field statements)
DefineConstant[ ShoreSizeMin = 10e3, ShoreSizeMax = 60e3, ShoreDistMax = 300e3, RegionalAccuracy = 5e3,
                RegionalMinChannelWidth = 2e3 ];
Include "regions.geo";
Include "ocean_fields.geo";
Call EarthSphere;
// ETOPO5 depths at the nodes of the fort.14 / hgrid.gr3 / UGRID file (5 m at least: the
// shallowest water a wetting-free run takes), and the Courant time step in the summary.
GulfDepth = newf;
Field[GulfDepth] = Bathymetry;
Field[GulfDepth].FileName = StrCat(BathyDir, "etopo5_global_0.25deg.nc");
Field[GulfDepth].Output = "depth";
Field[GulfDepth].MinDepth = 5;
Mesh.DepthField = GulfDepth;
Mesh.MinTimeStep = 10;
RegionalResolution = "i";   // GSHHG intermediate from the system (gmt-gshhg-high)
RegionalMinArea = 100;      // km^2
RegionalBox[] = {RegionGulfOfMexico[]};
RegionalSeaAt[] = {CentralGulfOfMexico[]};
Call RegionalSea;
ShorePoints[] = RegionalShorePoints[];  ShoreBox[] = RegionalBox[];
Call ShoreProximity;
OceanFields[] = {ShoreField};
Call OceanSize;

cl[] = Coastline{1, "Closures"};
For i In {0 : #cl[] - 1 : 3}
  If (Fabs(cl[i] + 80.6147) < 0.001 && Fabs(cl[i + 1] - 28.4105) < 0.001)
    Printf("closed at 80.61W 28.41N: width %.1f m", cl[i + 2]);
  EndIf
EndFor
// expect: closed at 80.61W 28.41N: width 97.3 m
Mesh 2;
