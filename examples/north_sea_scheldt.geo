// Figure 13 of Lambrechts et al. (2008), section 4.2: a multiscale mesh of the north-west
// European shelf for a model of the Scheldt estuary, whose tide is forced at the shelf break
// more than 1,000 km from the mouth: from about 150 m in the river near Antwerp to about
// 50 km far from the coasts (paper: 27,472 elements). Coastlines: GSHHG 2.3.7 full
// resolution from the system (Debian gmt-gshhg-full), cut to the polygon
// RegionNWEuropeanShelf (stdlib/regions.geo): open along the shelf break (the 200 m isobath
// of ETOPO5), across the shelf south of Brittany, the Norwegian Trench and the Skagerrak.
// Size field: the Min of
//   estuary: distance to points along the Scheldt, EstuarySize (150 m) within 3 km of
//            them, growing linearly to OffshoreSize (50 km) at EstuaryReach (400 km);
//   shore:   distance to the coast, CoastSize (5 km) on it to OffshoreSize at 300 km;
//   shelf break: distance to the open boundary along it, ShelfSize (10 km) on it to
//            OffshoreSize at ShelfReach (150 km): the tide enters there.
// The coastline accuracy gamma is the estuary criterion capped at CoastSize, so the river
// banks keep their detail and far coasts are coarsened to the mesh size.
//   stereomesh -0 examples/north_sea_scheldt.geo
// Smaller setting (tests/scripts/examples/north_sea_scheldt_coarse.geo): -setnumber
// EstuarySize 2000 -setnumber CoastSize 20e3.
DefineConstant[ EstuarySize = 150, CoastSize = 5e3, OffshoreSize = 50e3,
                EstuaryReach = 400e3, ShelfSize = 10e3, ShelfReach = 150e3, Quiet = 0, DoMesh = 0 ];
// DoMesh = 1 runs the `Mesh 2; Save` part at the end (or mesh with `stereomesh -2`).
DefineConstant[ ShoreSizeMin = CoastSize, ShoreSizeMax = OffshoreSize, ShoreDistMax = 300e3 ];
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";

Call EarthSphere;

// Points along the estuary, from the mouth (Vlissingen) up to Antwerp.
estuary_lon[] = {ScheldtMouth[0], 3.83, 4.03, 4.21, 4.29, Antwerp[0]};
estuary_lat[] = {ScheldtMouth[1], 51.35, 51.36, 51.40, 51.32, Antwerp[1]};
EstuaryPoints[] = {};
For i In {0 : #estuary_lon[] - 1}
  lon = estuary_lon[i];  lat = estuary_lat[i];
  Call LonLatPoint;
  EstuaryPoints[] += LonLatPointTag;
EndFor
Field[1] = Distance;
Field[1].PointsList = {EstuaryPoints[]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = EstuarySize;
Field[2].SizeMax = OffshoreSize;
Field[2].DistMin = 3e3;
Field[2].DistMax = EstuaryReach;
EstuaryField = 2;
Field[3] = MathEval;
Field[3].F = Sprintf("%.17g", CoastSize);
Field[4] = Min;                               // the coastline accuracy gamma
Field[4].FieldsList = {2, 3};

Coastline[1] = GSHHG;
Coastline[1].Resolution = "f";
Coastline[1].AccuracyField = 4;
// The shelf's polygon closes the cut coasts; its edges over water are the open boundaries.
Coastline[1].Region = {RegionNWEuropeanShelf[]};
Coastline[1].SeaAt = {ScheldtMouth[]};      // the shelf sea (not the pockets the polygon cuts off)
// GSHHG full stops at Bath (4.21E 51.40N): inside this box the OpenStreetMap banks of the
// Westerschelde and Zeeschelde (data/osm/scheldt_osm.txt, data/PROVENANCE.md) replace it,
// so the estuary reaches Antwerp. The box's edges cross the two data sets where they agree
// (the widest gap along them is the river's own width, where the south edge cuts it at
// Antwerp: the model's upstream end).
Coastline[1].Patch = StrCat(DataDir, "osm/scheldt_osm.txt");
Coastline[1].PatchBox = {4.15, 4.44, 51.21, 51.43};
OceanLoops[] = Coastline{1};
OceanLoopsPerSurface[] = Coastline{1, "LoopsPerSurface"};
open[] = Coastline{1, "OpenCurves"};
coast[] = Coastline{1, "CoastCurves"};
shelf[] = {};
For i In {0 : #NWEuropeanShelfBreakEdges[] - 1}   // an open curve runs along every edge it can
  shelf[] += Coastline{1, "OpenCurves", Sprintf("Edge%g", NWEuropeanShelfBreakEdges[i])};
EndFor
shelf[] = Unique(shelf[]);
Call OceanSurfaces;
Physical Surface("sea") = {OceanSurfaces[]};
Physical Curve("coast") = {coast[]};
Physical Curve("open") = {open[]};

ShorePoints[] = Coastline{1, "CoastPoints"};   // the coast without the open boundaries
// The estuary reaches Antwerp: a shore point within 3 km of it (GSHHG alone: 17 km).
AntwerpShore = newf;
Field[AntwerpShore] = Distance;
Field[AntwerpShore].PointsList = {ShorePoints[]};
Call ShoreProximity;
// The open boundary along the shelf break (with its two ends across the shelf, south of
// Brittany and over the Norwegian Trench): where the tide enters the model.
ShelfDistance = newf;
Field[ShelfDistance] = Distance;
Field[ShelfDistance].CurvesList = {shelf[]};
Field[ShelfDistance].NumPointsPerCurve = 200;
ShelfField = newf;
Field[ShelfField] = Threshold;
Field[ShelfField].InField = ShelfDistance;
Field[ShelfField].SizeMin = ShelfSize;
Field[ShelfField].SizeMax = OffshoreSize;
Field[ShelfField].DistMin = 0;
Field[ShelfField].DistMax = ShelfReach;
OceanFields[] = {EstuaryField, ShoreField, ShelfField};
Call OceanSize;

// Figures we can check before meshing.
seas = #OceanSurfaces[];
islands = #OceanLoops[] - seas;
lon = Antwerp[0]; lat = Antwerp[1]; Call LonLatToXYZ;
antwerp = FieldValue(SizeField, x, y, z);
antwerp_shore = FieldValue(AntwerpShore, x, y, z);
lon = ScheldtMouth[0]; lat = ScheldtMouth[1]; Call LonLatToXYZ;
mouth = FieldValue(SizeField, x, y, z);
lon = 2.5; lat = 51.8; Call LonLatToXYZ;        // 80 km off the mouth
off_mouth = FieldValue(SizeField, x, y, z);
off_mouth_by = FieldArgmin(MinSizeField, x, y, z);
lon = 3; lat = 56.5; Call LonLatToXYZ;          // central North Sea, 300 km from the coasts
offshore = FieldValue(SizeField, x, y, z);
offshore_by = FieldArgmin(MinSizeField, x, y, z);
If (!Quiet)
  Printf("%g seas, %g islands, %g open-boundary curves (%g along the shelf break), %g coast curves",
         seas, islands, #open[], #shelf[], #coast[]);
  Printf("Antwerp: %.0f m from the nearest shore point", antwerp_shore);
  Printf("size: Antwerp %.0f m, Scheldt mouth %.0f m, 80 km off it %.1f km, central North Sea %.1f km",
         antwerp, mouth, off_mouth / Km, offshore / Km);
EndIf
Assert(Fabs(antwerp - EstuarySize) < 1, "size at Antwerp %g m", antwerp);
Assert(antwerp_shore < 3e3, "the estuary reaches Antwerp: its nearest shore point is %g m away", antwerp_shore);
Assert(Fabs(mouth - EstuarySize) < 1, "size at the Scheldt mouth %g m", mouth);
// There the estuary's linear growth still decides (150 m + 77/397 of the way to 50 km).
Assert(off_mouth > 3 * EstuarySize && off_mouth < 0.5 * OffshoreSize && off_mouth_by == EstuaryField,
       "80 km off the mouth: %g m (criterion field %g)", off_mouth, off_mouth_by);
Assert(offshore > 0.7 * OffshoreSize && offshore <= OffshoreSize, "offshore size %g m", offshore);
Assert(#shelf[] == 1 && #open[] >= 1 && #coast[] > 0, "the polygon closes the cut coasts");

If (DoMesh)
  Mesh 2;
  Assert(Mesh.NbTriangles > 15000 && Mesh.NbTriangles < 80000);
  //   (the paper: 27,472 elements)
  Save "north_sea_scheldt.msh";
EndIf
