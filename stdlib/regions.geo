// Lon/lat boxes {W, E, S, N} (degrees) of the regions of Lambrechts et al. (2008), section 4,
// and places the examples refine around; the boxes match the regional GSHHG cuts in
// shared/data/gshhg (data/README.md). `Include "regions.geo";`, then e.g.
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

  // Places {lon, lat} (degrees).
  LizardIsland[] = {145.45, -14.67};             // Figure 14's refinement centre
  ScheldtMouth[] = {3.58, 51.42};                // Vlissingen, where the estuary opens
  Antwerp[] = {4.40, 51.23};                     // Figure 13's upstream end (150 m)

  // InBox: input lon, lat and box[] = {W, E, S, N}; output InBoxResult (1 inside or on the
  // edge, else 0). Longitudes are compared modulo 360, so boxes running past +-180 work.
  Macro InBox
    inbox_l_ = box[0] + Fmod(Fmod(lon - box[0], 360) + 360, 360);
    InBoxResult = inbox_l_ <= box[1] && lat >= box[2] && lat <= box[3];
  Return
EndIf
