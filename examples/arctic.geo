// Figure 11 of Lambrechts et al. (2008), section 4.1: the Arctic north of 50N for a sea ice
// model resolving the straits of the Canadian Arctic Archipelago (paper: 17,053 triangles,
// 20 km near the archipelago's islands, 40 km elsewhere near coasts, up to 300 km far from
// them). Coastlines: GSHHG 2.3.7 intermediate, islands >= 10 km^2, cut by GMT at 50N
// (arctic_i_A10.txt), closed along the 50N parallel (the "open" boundary); the North Pole
// lies inside the domain, which the PolarSphere (projected from the South Pole) handles.
// Size field: the Min of
//   archipelago: distance to the coast points inside RegionCanadianArchipelago,
//                ArchipelagoSize (20 km) on them to FarSize (300 km) at FarReach;
//   coasts:      distance to every coast point, CoastSize (40 km) to FarSize at FarReach.
// FarReach (800 km) is ours: the paper gives no reach, and the triangle count follows it
// (18,579 at 800 km, 24,870 at 1,500 km; docs/examples.md has the table).
// The coastline accuracy gamma is ArchipelagoSize in the archipelago's box, CoastSize
// elsewhere (a LonLat field over a MathEval of lon/lat in radians).
//   stereomesh -0 examples/arctic.geo
// Smaller setting (tests/scripts/examples/arctic_coarse.geo): -setnumber ArchipelagoSize
// 60e3 -setnumber CoastSize 120e3 -setnumber EstimateStep 2.
DefineConstant[ ArchipelagoSize = 20e3, CoastSize = 40e3, FarSize = 300e3, FarReach = 800e3,
                Quiet = 0, DoMesh = 0, EstimateStep = 0.5 ];
// DoMesh = 1 runs the `Mesh 2; Save` part at the end (or mesh with `stereomesh -2`).
// EstimateStep: lon/lat step (degrees) of the triangle-count estimate (0: skip it).
DefineConstant[ ShoreSizeMin = CoastSize, ShoreSizeMax = FarSize, ShoreDistMax = FarReach ];
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";

Call EarthSphere;

caa[] = RegionCanadianArchipelago[];
Field[1] = MathEval;                           // x = lon, y = lat in radians
// 1 inside the box: step(x - W) step(E - x) step(y - S) step(N - y), written with
// subtractions only (MathEval takes no sign after an operator).
Field[1].F = Sprintf("%.17g - %.17g * step(x - (%.17g)) * step(0 - x + (%.17g)) * step(y - (%.17g)) * step(0 - y + (%.17g))",
                     CoastSize, CoastSize - ArchipelagoSize, caa[0] * Deg2Rad, caa[1] * Deg2Rad,
                     caa[2] * Deg2Rad, caa[3] * Deg2Rad);
Field[2] = LonLat;
Field[2].InField = 1;
Field[2].RadiusStereo = EarthRadius;
Coastline[1] = LonLatText;
Coastline[1].FileName = StrCat(GshhgDir, "arctic_i_A10.txt");
Coastline[1].AccuracyField = 2;
OceanLoops[] = Coastline{1};
OceanLoopsPerSurface[] = Coastline{1, "LoopsPerSurface"};
open[] = Coastline{1, "OpenCurves"};
coast[] = Coastline{1, "Curves"};
coast[] -= open[];
Call OceanSurfaces;
Physical Surface("sea") = {OceanSurfaces[]};
Physical Curve("coast") = {coast[]};
Physical Curve("open") = {open[]};

// Every coast point (the 50N closing pieces dropped), and those in the archipelago.
ShorePoints[] = Coastline{1, "Points"};
ShoreBox[] = RegionArctic[];
Call ShoreProximity;
all_coast_field = ShoreField;
all_points[] = ShorePoints[];
caa_points[] = {};
box[] = caa[];
For i In {0 : #all_points[] - 1}
  p[] = Point{all_points[i]};
  x = p[0];  y = p[1];  z = p[2];
  Call XYZToLonLat;
  Call InBox;
  If (InBoxResult)
    caa_points[] += all_points[i];
  EndIf
EndFor
ShorePoints[] = caa_points[];
ShoreSizeMin = ArchipelagoSize;
Call ShoreProximity;
caa_field = ShoreField;
OceanFields[] = {caa_field, all_coast_field};
Call OceanSize;

// Figures we can check before meshing.
seas = #OceanSurfaces[];
islands = #OceanLoops[] - seas;
If (!Quiet)
  Printf("%g seas, %g islands, %g open-boundary curves, %g coast points (%g in the archipelago)",
         seas, islands, #open[], #all_points[], #caa_points[]);
EndIf
// Sizes: Barrow Strait in the archipelago (74.3N 95W), the Barents Sea coast of Norway
// (71N 25E), the North Pole and the Labrador Sea (56N 53W).
names[] = Str("Barrow Strait", "off northern Norway", "North Pole", "Labrador Sea");
lons[] = {-95, 25, 0, -53};
lats[] = {74.3, 71.2, 90, 56};
For i In {0 : 3}
  lon = lons[i];  lat = lats[i];  Call LonLatToXYZ;
  sizes[i] = FieldValue(SizeField, x, y, z);
  If (!Quiet)
    Printf(StrCat("size ", names[i], ": %.1f km"), sizes[i] / Km);
  EndIf
EndFor
// Barrow Strait is about 60 km wide: the archipelago criterion, 30 km from its coasts.
Assert(sizes[0] < 1.5 * ArchipelagoSize && sizes[0] < CoastSize, "Barrow Strait %g m", sizes[0]);
Assert(sizes[1] > ArchipelagoSize && sizes[1] <= 1.5 * CoastSize, "off Norway %g m", sizes[1]);
Assert(sizes[2] > 1.2 * CoastSize && sizes[2] <= FarSize, "North Pole %g m", sizes[2]);

If (EstimateStep > 0)
  EstimateDepthField = newf;
  Field[EstimateDepthField] = Bathymetry;
  Field[EstimateDepthField].FileName = StrCat(BathyDir, "etopo5_global_0.25deg.nc");
  EstimateBox[] = RegionArctic[];
  Call EstimateTriangles;
  If (!Quiet)
    Printf("estimate: %.0f triangles over %.0f km^2 of water (paper, Figure 11: 17,053)",
           EstimatedTriangles, EstimatedWaterArea / 1e6);
  EndIf
EndIf

If (DoMesh)
  Mesh 2;
  Assert(Mesh.NbTriangles > 10000 && Mesh.NbTriangles < 30000);
  Save "arctic.msh";
EndIf
