// Figure 14 of Lambrechts et al. (2008), section 4.3: a coarse mesh of the Great Barrier
// Reef refined around Lizard Island (paper: 20,384 elements, 70% of them in the refined
// region). Coastlines: GSHHG 2.3.7 full resolution cut by GMT to 142/154/-25/-10
// (gbr_lizard_f.txt, which holds no coral reefs: GSHHG has none), closed along that box.
// Size field: the Min of
//   Lizard:   distance to Lizard Island, LizardSize (250 m) within LizardCore (10 km: the
//             island, its reef passages and wakes), growing to
//             ShelfSize (20 km) at LizardReach (60 km), no constraint beyond;
//   shore:    CoastSize (5 km) on the coast to 50 km at 200 km;
//   f1, f2:   the bathymetry criteria of section 3.1 on ETOPO5 (5'): the wavelength with
//             lambda_min / N = 30 km at 4000 m, 10-50 km (the deep Coral Sea stays coarse,
//             the paper's "only used as boundary conditions"), the Hessian LizardSize to
//             50 km (the reef shelf break).
// The coastline accuracy gamma is the Lizard criterion capped at CoastSize.
//   stereomesh -0 examples/great_barrier_reef.geo
// Smaller setting (tests/scripts/examples/great_barrier_reef_coarse.geo): -setnumber
// LizardSize 1000 -setnumber CoastSize 20e3.
DefineConstant[ LizardSize = 250, LizardCore = 10e3, CoastSize = 5e3, ShelfSize = 20e3, LizardReach = 60e3,
                Quiet = 0, DoMesh = 0, EstimateStep = 0.1, EstimateFineStep = 0.01 ];
// EstimateStep: lon/lat step (degrees) of the triangle-count estimate (0: skip it); the
// degree around Lizard Island is summed at EstimateFineStep.
// DoMesh = 1 runs the `Mesh 2; Save` part at the end (or mesh with `stereomesh -2`).
DefineConstant[ ShoreSizeMin = CoastSize, ShoreSizeMax = 50e3, ShoreDistMax = 200e3,
                WaveLengthMin = 300e3, WaveSizeMin = 10e3, WaveSizeMax = 50e3,
                HessianSizeMin = LizardSize, HessianSizeMax = 50e3 ];
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";

Call EarthSphere;

lon = LizardIsland[0];  lat = LizardIsland[1];
Call LonLatPoint;
lizard_point = LonLatPointTag;
Field[1] = Distance;
Field[1].PointsList = {lizard_point};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = LizardSize;
Field[2].SizeMax = ShelfSize;
Field[2].DistMin = LizardCore;
Field[2].DistMax = LizardReach;
Field[2].StopAtDistMax = 1;                   // no constraint beyond LizardReach
LizardField = 2;
Field[3] = MathEval;
Field[3].F = Sprintf("%.17g", CoastSize);
Field[4] = Min;                               // the coastline accuracy gamma
Field[4].FieldsList = {2, 3};

Coastline[1] = LonLatText;
Coastline[1].FileName = StrCat(GshhgDir, "gbr_lizard_f.txt");
Coastline[1].AccuracyField = 4;
OceanLoops[] = Coastline{1};
OceanLoopsPerSurface[] = Coastline{1, "LoopsPerSurface"};
open[] = Coastline{1, "OpenCurves"};
coast[] = Coastline{1, "Curves"};
coast[] -= open[];
Call OceanSurfaces;
Physical Surface("sea") = {OceanSurfaces[]};
Physical Curve("coast") = {coast[]};
Physical Curve("open") = {open[]};

ShorePoints[] = Coastline{1, "Points"};
ShoreBox[] = RegionGBR[];
Call ShoreProximity;
BathyFile = StrCat(BathyDir, "etopo5_gbr_5min.nc");
Call WaveLength;
Call BathyHessian;
OceanFields[] = {LizardField, ShoreField, WaveField, HessianField};
Call OceanSize;

// Figures we can check before meshing.
seas = #OceanSurfaces[];
islands = #OceanLoops[] - seas;
lon = LizardIsland[0];  lat = LizardIsland[1];  Call LonLatToXYZ;
lizard = FieldValue(SizeField, x, y, z);
// Lizard Island (about 3 km across) is kept as an island: a coast point lies within 2 km of
// its centre. Coarsened away, the nearest coast would be the mainland, 30 km west.
lizard_shore = FieldValue(ShoreDistanceField, x, y, z);
lon = 152; lat = -15; Call LonLatToXYZ;         // Coral Sea, 2-4 km deep, far from coasts
coral_sea = FieldValue(SizeField, x, y, z);
coral_sea_by = FieldArgmin(MinSizeField, x, y, z);
If (!Quiet)
  Printf("%g seas, %g islands, %g open-boundary curves", seas, islands, #open[]);
  Printf("Lizard Island: coast %.1f km from its centre, size %.0f m", lizard_shore / Km, lizard);
  Printf("Coral Sea: size %.1f km (criterion field %g)", coral_sea / Km, coral_sea_by);
EndIf
Assert(lizard_shore < 2e3, "Lizard Island is not in the model (coast %g m away)", lizard_shore);
Assert(Fabs(lizard - LizardSize) < 1, "size at Lizard Island %g m", lizard);
// The deep Coral Sea: a bathymetry criterion decides, coarser than the shelf's ShelfSize.
Assert((coral_sea_by == WaveField || coral_sea_by == HessianField) && coral_sea > ShelfSize,
       "Coral Sea: %g m by field %g", coral_sea, coral_sea_by);

If (EstimateStep > 0)
  EstimateDepthField = newf;
  Field[EstimateDepthField] = Bathymetry;
  Field[EstimateDepthField].FileName = BathyFile;
  EstimateBox[] = RegionGBR[];
  EstimateFineBox[] = {145, 146, -15.2, -14.2};
  Call EstimateTriangles;
  all_triangles = EstimatedTriangles;
  // The refined region alone (within LizardReach of the island).
  EstimateBox[] = EstimateFineBox[];
  EstimateStep = EstimateFineStep;
  EstimateFineBox[] = {1, 0, 1, 0};
  Call EstimateTriangles;
  If (!Quiet)
    Printf("estimate: %.0f triangles, %.0f%% of them within 0.5 degree of Lizard Island (paper, Figure 14: 20,384, 70%% in the refined region)",
           all_triangles, 100 * EstimatedTriangles / all_triangles);
  EndIf
EndIf

If (DoMesh)
  Mesh 2;
  Assert(Mesh.NbTriangles > 10000 && Mesh.NbTriangles < 40000);
  //   (the paper: 20,384 elements, 70% of them near Lizard Island)
  Save "great_barrier_reef.msh";
EndIf
