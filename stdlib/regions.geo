// Lon/lat boxes {W, E, S, N} (degrees) of the regions of Lambrechts et al. (2008), section 4,
// and places the examples refine around; the boxes match the regional GSHHG cuts in
// data/gshhg (data/PROVENANCE.md). `Include "regions.geo";`, then e.g.
// `Coastline[1].Region = {RegionGBR[]};` or `box[] = RegionArctic[]; Call InBox;`.
//
// Included twice (e.g. by a script and by another stdlib file), the second Include does
// nothing: macros cannot be redefined.
If (!Exists(RegionsGeoLoaded))
  RegionsGeoLoaded = 1;
  RegionGBIreland[] = {-11, 2, 49, 61};          // Figures 5 and 8: Great Britain and Ireland
  RegionNorthSeaScheldt[] = {-4, 9, 48, 58};     // Figure 13: North Sea and the Scheldt
  RegionGBR[] = {142, 154, -25, -10};            // Figure 14: Great Barrier Reef
  RegionArctic[] = {-180, 180, 50, 90};          // Figure 11: north of 50N
  RegionCanadianArchipelago[] = {-130, -60, 60, 84};   // Figure 11's 20 km zone
  RegionNorthPacific[] = {150, 240, 20, 62};     // Figure 10's close-up
  RegionMediterranean[] = {-5.6, 37, 29, 46.5};  // from Gibraltar; holds the Black Sea's west and the Suez Canal
  RegionGulfOfMexico[] = {-98, -76, 7, 31};      // with the western Caribbean; holds the Panama Canal
  // Figure 13's domain, a polygon {lon1, lat1, lon2, lat2, ...} with great-circle edges: the
  // north-west European shelf, open along the shelf break from the Bay of Biscay to the
  // Norwegian Trench. Vertices 2 to 16 lie on the 200 m isobath of ETOPO5 (west-most, or
  // north-most, cell deeper than 200 m every half degree or degree in
  // data/bathymetry/etopo5_nw_europe_5min.nc, thinned by hand); 17 to 19 in the Norwegian
  // Trench and the Skagerrak, off Norway's fjords; the others inland (Denmark, Germany,
  // France, Brittany). So the open boundary runs in one piece from south Brittany (edge 1,
  // across the shelf) along the shelf break (edges 2 to 15) and down the trench to
  // Denmark's north coast (edges 16 to 19).
  RegionNWEuropeanShelf[] = {-2.5, 48.0,  -6.33, 47.5,  -9.42, 48.5,  -11.0, 49.5,  -10.75, 50.5,
                             -11.42, 52.0,  -11.9, 53.2,  -10.58, 54.5,  -9.42, 55.5,  -9.0, 57.0,
                             -9.25, 58.0,  -6.92, 59.0,  -4.83, 60.0,  -2.0, 60.92,  0.0, 61.58,
                             2.0, 61.42,  4.0, 60.0,  4.2, 58.6,  6.5, 57.7,  10.0, 57.3,
                             9.5, 54.0,  6.0, 51.0,  3.0, 49.5,  -1.0, 48.5};
  NWEuropeanShelfBreakEdges[] = {2 : 15};

  // Places {lon, lat} (degrees).
  LizardIsland[] = {145.45, -14.67};             // Figure 14's refinement centre
  ScheldtMouth[] = {3.58, 51.42};                // Vlissingen, where the estuary opens
  CentralMediterranean[] = {18, 35};             // the Ionian Sea, south of Italy
  CentralGulfOfMexico[] = {-90, 25};
  Antwerp[] = {4.40, 51.23};                     // Figure 13's upstream end (150 m)

  // RegionalSea: the whole set-up of a regional sea (docs/coastlines.md, "Regional seas").
  // Input:
  //  - the shoreline: RegionalResolution (GSHHG from the system: "c", "l", "i", "h" or "f")
  //    or RegionalFile (a shoreline file, relative to the script) read as RegionalFormat
  //    (default "LonLatText"; "GSHHS" a GSHHS binary, "Shapefile", "GSHHG" a
  //    binned_GSHHS_*.nc, "Loops2": the formats of `Coastline[n] = ...;`, any case);
  //    RegionalMinArea (km^2) drops smaller islands and lakes;
  //  - the region: RegionalBox[] = {W, E, S, N}, or a polygon {lon1, lat1, lon2, lat2, lon3,
  //    lat3, ...} with great-circle edges (Coastline's Region), or RegionalRegionFile (a
  //    shapefile holding that polygon, Coastline's RegionFile);
  //  - the accuracy (the coastline's gamma): RegionalAccuracy (m, default 5 km) or
  //    RegionalAccuracyField (a size field id giving gamma in metres), not both;
  //  - optionally RegionalSeaAt[] = {lon, lat, ...} (keep only the seas holding these
  //    points), RegionalMinChannelWidth (m: close passages narrower than this),
  //    RegionalKeepOpen[] = {lon, lat, ...} (the passages at these points stay open),
  //    RegionalDams[] = {lon1, lat1, lon2, lat2, ...} and RegionalCoastline (the Coastline
  //    id, default 1).
  // Needs a PolarSphere (Call EarthSphere). Makes the sea surfaces and the physical groups
  // "sea", "coast" (shores and dams) and "open" (the region's sides crossing the kept seas).
  // Output: RegionalSurfaces[], RegionalCoastCurves[], RegionalOpenCurves[],
  // RegionalAccuracyField (the one given, or a MathEval of RegionalAccuracy) and
  // RegionalShorePoints[], the coast's points for ShoreProximity's ShorePoints[]. ShoreBox[]
  // is there to drop the open sea's points from them: with a box they are every control
  // point (Coastline's "Points"), so set ShoreBox[] = RegionalBox[] and ShoreProximity
  // leaves out those on the box's sides; with a polygon they are the coast curves' points
  // only (Coastline's "CoastPoints"), so leave ShoreBox[] unset (it takes a box only).
  Macro RegionalSea
    If ((!Exists(RegionalFile) && !Exists(RegionalResolution)) || (!Exists(RegionalBox[]) && !Exists(RegionalRegionFile)))
      Error("RegionalSea: set RegionalResolution (GSHHG from the system) or RegionalFile, and RegionalBox[] (a box {W, E, S, N} or a polygon) or RegionalRegionFile first");
      Abort;
    EndIf
    If (Exists(RegionalBox[]) && Exists(RegionalRegionFile))
      Error("RegionalSea: set RegionalBox[] or RegionalRegionFile, not both: the region is either written or read from a file");
      Abort;
    EndIf
    If (Exists(RegionalBox[]))
      If (#RegionalBox[] != 4 && (#RegionalBox[] < 6 || #RegionalBox[] % 2 != 0))
        Error("RegionalSea: RegionalBox[] holds %g numbers: it takes a box {W, E, S, N} or a polygon {lon1, lat1, lon2, lat2, lon3, lat3, ...}", #RegionalBox[]);
        Abort;
      EndIf
    EndIf
    regional_id_ = Exists(RegionalCoastline) ? RegionalCoastline : 1;
    // RegionalAccuracyField is also an output: the MathEval an earlier Call made from
    // RegionalAccuracy is not a field the script gave, and is made again.
    regional_given_field_ = Exists(RegionalAccuracyField);
    If (regional_given_field_ && Exists(RegionalMadeAccuracyField_))
      If (RegionalAccuracyField == RegionalMadeAccuracyField_)
        regional_given_field_ = 0;
      EndIf
    EndIf
    If (regional_given_field_ && Exists(RegionalAccuracy))
      Error("RegionalSea: set RegionalAccuracy (a constant gamma) or RegionalAccuracyField (a size field), not both");
      Abort;
    EndIf
    If (!regional_given_field_)
      RegionalAccuracyField = newf;
      RegionalMadeAccuracyField_ = RegionalAccuracyField;
      Field[RegionalAccuracyField] = MathEval;
      Field[RegionalAccuracyField].F = Sprintf("%g", Exists(RegionalAccuracy) ? RegionalAccuracy : 5e3);
    EndIf
    If (Exists(RegionalResolution))
      Coastline[regional_id_] = GSHHG;
      Coastline[regional_id_].Resolution = RegionalResolution;
    Else
      // `Coastline[n] = ...;` names its format as a word, so the string is matched here.
      regional_format_ = "LONLATTEXT";
      If (Exists(RegionalFormat))
        regional_format_ = UpperCase(RegionalFormat);
      EndIf
      If (!StrCmp(regional_format_, "LONLATTEXT"))
        Coastline[regional_id_] = LonLatText;
      ElseIf (!StrCmp(regional_format_, "GSHHS"))
        Coastline[regional_id_] = GSHHS;
      ElseIf (!StrCmp(regional_format_, "SHAPEFILE"))
        Coastline[regional_id_] = Shapefile;
      ElseIf (!StrCmp(regional_format_, "GSHHG"))
        Coastline[regional_id_] = GSHHG;
      ElseIf (!StrCmp(regional_format_, "LOOPS2"))
        Coastline[regional_id_] = Loops2;
      Else
        Error("RegionalSea: RegionalFormat '%s' is not a shoreline format: LonLatText, GSHHS, Shapefile, GSHHG or Loops2", RegionalFormat);
        Abort;
      EndIf
      Coastline[regional_id_].FileName = RegionalFile;
    EndIf
    If (Exists(RegionalMinArea))
      Coastline[regional_id_].MinArea = RegionalMinArea;
    EndIf
    Coastline[regional_id_].AccuracyField = RegionalAccuracyField;
    If (Exists(RegionalRegionFile))
      Coastline[regional_id_].RegionFile = RegionalRegionFile;
    Else
      Coastline[regional_id_].Region = {RegionalBox[]};
    EndIf
    If (Exists(RegionalMinChannelWidth))
      Coastline[regional_id_].MinChannelWidth = RegionalMinChannelWidth;
    EndIf
    If (Exists(RegionalDams[]))
      Coastline[regional_id_].Dams = {RegionalDams[]};
    EndIf
    If (Exists(RegionalKeepOpen[]))
      Coastline[regional_id_].KeepOpen = {RegionalKeepOpen[]};
    EndIf
    If (Exists(RegionalSeaAt[]))
      Coastline[regional_id_].SeaAt = {RegionalSeaAt[]};
    EndIf
    RegionalSurfaces[] = Coastline{regional_id_, "Surfaces"};
    RegionalCoastCurves[] = Coastline{regional_id_, "CoastCurves"};
    RegionalOpenCurves[] = Coastline{regional_id_, "OpenCurves"};
    Physical Surface("sea") = {RegionalSurfaces[]};
    Physical Curve("coast") = {RegionalCoastCurves[]};
    If (#RegionalOpenCurves[] > 0)
      Physical Curve("open") = {RegionalOpenCurves[]};
    EndIf
    regional_is_box_ = 0;
    If (Exists(RegionalBox[]))
      regional_is_box_ = #RegionalBox[] == 4;
    EndIf
    If (regional_is_box_)
      // Every control point of the kept seas: with ShoreBox[] = RegionalBox[], ShoreProximity
      // leaves out those on the box (open sea).
      RegionalShorePoints[] = Coastline{regional_id_, "Points"};
    Else
      // A polygon's open curves run along great circles, which no box test finds: take the
      // coast curves' points, the open boundaries' own points left out.
      RegionalShorePoints[] = Coastline{regional_id_, "CoastPoints"};
    EndIf
  Return

  // InBox: input lon, lat and box[] = {W, E, S, N}; output InBoxResult (1 inside or on the
  // edge, else 0). Longitudes are compared modulo 360, so boxes running past +-180 work.
  Macro InBox
    inbox_l_ = box[0] + Fmod(Fmod(lon - box[0], 360) + 360, 360);
    InBoxResult = inbox_l_ <= box[1] && lat >= box[2] && lat <= box[3];
  Return
EndIf
