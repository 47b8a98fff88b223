// Figures 9-10 of Lambrechts et al. (2008), section 4.1: the World Ocean on the sphere,
// meshed in the stereographic plane of a PolarSphere projected from the South Pole
// (Antarctica's coast is the outer loop). Size field (section 3.1), all three criteria:
//   shore proximity: 30 km on the coast to 200 km at 500 km from it,
//   wavelength from the ETOPO5 bathymetry: lambda_min / N sqrt(H_ref / H), 25-500 km,
//   bathymetry Hessian: 1 / sqrt(|lambda_max|) of H / H_ref, 25-500 km,
// combined by a Min. Coastlines: GSHHG 2.3.7 intermediate (islands >= 100 km^2) from the
// system (Debian gmt-gshhg-high), coarsened to the accuracy gamma = CoastAccuracy (30 km,
// the smallest mesh size near the coast).
//   stereomesh -0 examples/world_ocean.geo              (evaluate and check)
//   stereomesh -2 examples/world_ocean.geo -o world.msh (mesh and write it)
// Smaller settings (tests/scripts/examples/world_ocean_coarse.geo): -setnumber CoastAccuracy
// 200e3 -setstring CoastResolution l -setnumber CoastMinArea 0 -setstring BathyName
// etopo5_global_1deg.nc. The whole full-resolution GSHHG: -setstring CoastResolution f.
// Paper: 436,409 triangles in 35 s (whole process). docs/examples.md has our numbers.
// The paper gives the criteria's ranges but not lambda_min / N; 50 km where the ocean is
// 4000 m deep (f1 grows where it is shallower: sqrt(H_ref / H)) brings the open ocean to
// about the paper's mean size. Set before the Include: ocean_fields.geo's DefineConstant
// keeps it.
DefineConstant[ WaveLengthMin = 500e3 ];
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";

DefineConstant[ CoastAccuracy = 30e3, CoastResolution = "i", CoastMinArea = 100,
                BathyName = "etopo5_global_0.25deg.nc", Quiet = 0, DoMesh = 0,
                EstimateStep = 0, CloseStraits = 1, CloseNarrowWater = 1, CoastDeviation = 0.5 ];
// EstimateStep: lon/lat step (degrees) of the triangle-count estimate (0: skip it; 1 takes
// about 20 s of CPU).
// DoMesh = 1 runs the `Mesh 2; Save` part at the end (stereomesh -0 ... -setnumber DoMesh 1);
// `stereomesh -2 examples/world_ocean.geo` meshes after the script instead.

Call EarthSphere;

Field[1] = MathEval;
Field[1].F = Sprintf("%.17g", CoastAccuracy);
Coastline[1] = GSHHG;
Coastline[1].Resolution = CoastResolution;   // c, l, i, h, f (docs/coastlines.md)
Coastline[1].MinArea = CoastMinArea;         // km^2, as GMT's -A
Coastline[1].AccuracyField = 1;
Coastline[1].AntarcticaLevel = 5;            // the ice front, as GSHHS level 5
// Straits narrower than gamma closed (the two islands merged): without this the coasts'
// 1D mesh crosses itself in the Singapore Strait at 30 km (curves near 101.46E 1.75N).
Coastline[1].CloseStraits = CloseStraits;
// Water narrower than gamma that ends (the Coorong lagoon, the Suez Canal's ends, fjords)
// is not in the coast as drawn either: left open, its triangles have all three nodes on
// the coast, below the 0.3 floor. It is filled up to its mouth; passages between two waters
// (Gibraltar, the Bosporus) stay open.
Coastline[1].MinChannelWidth = CloseNarrowWater ? CoastAccuracy : 0;
Coastline[1].KeepPassages = 1;
// The coast curve within CoastDeviation * gamma of the GSHHG points (source points put back
// where the B-spline cuts a headland or a bay; 0.5, the import's default, keeps it within
// gamma / 2); 0 leaves the curve as coarsening makes it and only reports how far it lies
// from the data (docs/coastlines.md, "The curve within a bound of the data").
Coastline[1].DeviationFactor = CoastDeviation;

OceanLoops[] = Coastline{1};
OceanLoopsPerSurface[] = Coastline{1, "LoopsPerSurface"};
counts[] = Coastline{1, "ControlPoints"};
Call OceanSurfaces;
Physical Surface("ocean") = {OceanSurfaces[]};
Physical Curve("coast") = Coastline{1, "Curves"};

// The criteria, with the paper's values (ocean_fields.geo's defaults, WaveLengthMin above).
ShorePoints[] = Coastline{1, "Points"};
Call ShoreProximity;
BathyFile = StrCat(BathyDir, BathyName);
Call WaveLength;
Call BathyHessian;
OceanFields[] = {ShoreField, WaveField, HessianField};
Call OceanSize;

// Figures we can check before meshing.
islands = OceanLoopsPerSurface[0] - 1;   // holes of the World Ocean
seas = #OceanSurfaces[];
points = 0;
For i In {0 : #counts[] - 1}
  points += counts[i];
EndFor
If (!Quiet)
  Printf("gamma %g km: %g sea(s), %g islands, %g control points", CoastAccuracy / Km, seas,
         islands, points);
EndIf
// The Pacific (Antarctica's ice front as the outer loop) is one connected ocean with the
// Atlantic and the Indian Ocean: the largest surface holds every continent as a hole.
Assert(seas >= 1 && OceanLoopsPerSurface[0] > 3, "the World Ocean surface has no islands");

// Size at known places (FieldValue at 3D points of the sphere, metres).
// Mid-Pacific, 5 km deep, more than 500 km from any coast: 50 km sqrt(4000 / 5000) from
// the wavelength, unless the Hessian of a seamount asks for less; never the shore.
lon = -140; lat = 10; Call LonLatToXYZ;
pacific = FieldValue(SizeField, x, y, z);
pacific_by = FieldArgmin(MinSizeField, x, y, z);
pacific_wave = FieldValue(WaveField, x, y, z);
// On the Dogger Bank in the North Sea (20-40 m deep) f1 is large (coarse); the shore
// criterion (about 150 km offshore) decides.
lon = 2.5; lat = 55; Call LonLatToXYZ;
shelf = FieldValue(SizeField, x, y, z);
shelf_by = FieldArgmin(MinSizeField, x, y, z);
shelf_wave = FieldValue(WaveField, x, y, z);
// On a coast point the shore criterion gives its ShoreSizeMin (30 km).
xyz[] = Point{ShorePoints[0]};
coast = FieldValue(SizeField, xyz[0], xyz[1], xyz[2]);
If (!Quiet)
  Printf("size: mid-Pacific %.1f km (wavelength %.1f km), Dogger Bank %.1f km (wavelength %.0f km), coast %.1f km",
         pacific / Km, pacific_wave / Km, shelf / Km, shelf_wave / Km, coast / Km);
EndIf
Assert(pacific_wave > 40e3 && pacific_wave < 55e3, "mid-Pacific wavelength size %g m", pacific_wave);
Assert(pacific_by != ShoreField && pacific <= pacific_wave, "the shore criterion acts 500 km offshore");
Assert(shelf_wave > 200e3 && shelf_by == ShoreField, "shelf: wavelength %g m, criterion field %g",
       shelf_wave, shelf_by);
Assert(Fabs(coast - ShoreSizeMin) < 1, "size on the coast %g m", coast);

// Figure 10: in the North Pacific close-up "the effects of the three refinement rules are
// clearly visible". Which criterion sets the size, on a 2-degree grid of water points?
np[] = RegionNorthPacific[];
depth_field = newf;
Field[depth_field] = Bathymetry;
Field[depth_field].FileName = BathyFile;
by_shore = 0;  by_wave = 0;  by_hessian = 0;
For lat In {np[2] + 1 : np[3] - 1 : 2}
  For lon In {np[0] + 1 : np[1] - 1 : 2}
    Call LonLatToXYZ;
    If (FieldValue(depth_field, x, y, z) > MinDepth)
      which = FieldArgmin(MinSizeField, x, y, z);
      by_shore += which == ShoreField;
      by_wave += which == WaveField;
      by_hessian += which == HessianField;
    EndIf
  EndFor
EndFor
np_total = by_shore + by_wave + by_hessian;
If (!Quiet)
  Printf("North Pacific (Figure 10), %g water points: shore %.0f%%, wavelength %.0f%%, Hessian %.0f%%",
         np_total, 100 * by_shore / np_total, 100 * by_wave / np_total, 100 * by_hessian / np_total);
EndIf
Assert(by_shore > 0 && by_wave > 0 && by_hessian > 0, "a criterion never acts in the North Pacific");

If (EstimateStep > 0)
  EstimateDepthField = newf;
  Field[EstimateDepthField] = Bathymetry;
  Field[EstimateDepthField].FileName = BathyFile;
  EstimateBox[] = {-180, 180, -90, 90};
  Call EstimateTriangles;
  If (!Quiet)
    Printf("estimate: %.0f triangles over %.0f km^2 of water (paper, Figure 9: 436,409)",
           EstimatedTriangles, EstimatedWaterArea / 1e6);
  EndIf
EndIf

If (DoMesh)
  Mesh 2;
  Assert(Mesh.NbTriangles > 300000 && Mesh.NbTriangles < 600000);
  //   (the paper: 436,409 triangles)
  Save "world_ocean.msh";
EndIf
