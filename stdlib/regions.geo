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
  // Input: the shoreline, either RegionalResolution (GSHHG from the system: "c", "l", "i",
  // "h" or "f"; RegionalMinArea in km^2 drops smaller islands and lakes) or RegionalFile (a
  // LonLatText shoreline file); RegionalBox[] = {W, E, S, N}; and
  // optionally RegionalAccuracy (m, default 5 km: the coastline's gamma), RegionalSeaAt[] =
  // {lon, lat, ...} (keep only the seas holding these points), RegionalMinChannelWidth (m:
  // close passages narrower than this), RegionalKeepOpen[] = {lon, lat, ...} (the passages
  // at these points stay open), RegionalDams[] = {lon1, lat1, lon2, lat2, ...} and
  // RegionalCoastline (the Coastline id, default 1). Needs a PolarSphere (Call EarthSphere).
  // Makes the sea surfaces and the physical groups "sea", "coast" (shores and dams) and
  // "open" (the box sides crossing the kept seas). Output: RegionalSurfaces[],
  // RegionalCoastCurves[], RegionalOpenCurves[], RegionalShorePoints[] (the control
  // points, for ShoreProximity with ShoreBox[] = RegionalBox[]) and RegionalAccuracyField.
  Macro RegionalSea
    If ((!Exists(RegionalFile) && !Exists(RegionalResolution)) || !Exists(RegionalBox[]))
      Error("RegionalSea: set RegionalResolution (GSHHG from the system) or RegionalFile, and RegionalBox[] = {W, E, S, N} first");
      Abort;
    EndIf
    regional_id_ = Exists(RegionalCoastline) ? RegionalCoastline : 1;
    RegionalAccuracyField = newf;
    Field[RegionalAccuracyField] = MathEval;
    Field[RegionalAccuracyField].F = Sprintf("%g", Exists(RegionalAccuracy) ? RegionalAccuracy : 5e3);
    If (Exists(RegionalResolution))
      Coastline[regional_id_] = GSHHG;
      Coastline[regional_id_].Resolution = RegionalResolution;
      If (Exists(RegionalMinArea))
        Coastline[regional_id_].MinArea = RegionalMinArea;
      EndIf
    Else
      Coastline[regional_id_] = LonLatText;
      Coastline[regional_id_].FileName = RegionalFile;
    EndIf
    Coastline[regional_id_].AccuracyField = RegionalAccuracyField;
    Coastline[regional_id_].Region = {RegionalBox[]};
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
    // Every control point of the kept seas: with ShoreBox[] = RegionalBox[], ShoreProximity
    // leaves out those on the box (open sea).
    RegionalShorePoints[] = Coastline{regional_id_, "Points"};
  Return

  // InBox: input lon, lat and box[] = {W, E, S, N}; output InBoxResult (1 inside or on the
  // edge, else 0). Longitudes are compared modulo 360, so boxes running past +-180 work.
  Macro InBox
    inbox_l_ = box[0] + Fmod(Fmod(lon - box[0], 360) + 360, 360);
    InBoxResult = inbox_l_ <= box[1] && lat >= box[2] && lat <= box[3];
  Return
EndIf
