// Figures 5 and 8 of Lambrechts et al. (2008): Great Britain and Ireland from GSHHG 2.3.7
// full resolution (gb_ireland_f.txt, closed along its -11/2/49/61 box across France).
// Figure 5 (coastline coarsening at gamma = 100 km, 15 km, 1.5 km, 150 m) is
// gb_ireland_coarsening.geo, included here: it checks the island and control point counts.
// Figure 8 meshes the 15 km model with a shore proximity function as the only size field
// (paper: 18,698 / 19,514 / 17,154 triangles with three algorithms; the paper gives no
// sizes: ours, CoastSize 5 km on the coast to FarSize 30 km at 200 km, give about that many
// by the estimate below).
//   stereomesh -0 examples/gb_ireland.geo [-setnumber gamma 1500]
DefineConstant[ gamma = 15000, CoastSize = 5e3, FarSize = 30e3, ShoreReach = 200e3,
                Quiet = 0, DoMesh = 0, EstimateStep = 0.1 ];
// DoMesh = 1 runs the `Mesh 2; Save` part at the end (or mesh with `stereomesh -2`).
// EstimateStep: lon/lat step (degrees) of the triangle-count estimate (0: skip it).
DefineConstant[ ShoreSizeMin = CoastSize, ShoreSizeMax = FarSize, ShoreDistMax = ShoreReach ];
quiet = Quiet;
EarthRadius = 6371009;                         // the radius gb_ireland_coarsening.geo uses
MeshAtAccuracy = 0;                            // the sizes are the shore field's below
Include "gb_ireland_coarsening.geo";           // PolarSphere(1), Coastline[1], Plane Surface(1)
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";
EarthSphereTag = 1;

coast[] = Coastline{1, "Curves"};
coast[] -= open[];
Physical Surface("sea") = {1};
Physical Curve("coast") = {coast[]};
Physical Curve("open") = {open[]};

ShorePoints[] = Coastline{1, "Points"};
ShoreBox[] = RegionGBIreland[];
Call ShoreProximity;
OceanFields[] = {ShoreField};
Call OceanSize;

// Sizes at known places: the Irish Sea between Dublin and Holyhead (about 50 km from
// either coast) and the Atlantic west of Ireland, farther than ShoreReach from any coast.
lon = -5.4; lat = 53.35; Call LonLatToXYZ;
irish_sea = FieldValue(SizeField, x, y, z);
lon = -10.8; lat = 49.3; Call LonLatToXYZ;
atlantic = FieldValue(SizeField, x, y, z);
If (!Quiet)
  Printf("size: Irish Sea %.1f km, Atlantic %.1f km", irish_sea / Km, atlantic / Km);
EndIf
Assert(irish_sea > CoastSize && irish_sea < 0.5 * (CoastSize + FarSize), "Irish Sea %g m", irish_sea);
Assert(Fabs(atlantic - FarSize) < 1, "Atlantic %g m", atlantic);

If (EstimateStep > 0)
  EstimateDepthField = newf;
  Field[EstimateDepthField] = Bathymetry;
  Field[EstimateDepthField].FileName = StrCat(BathyDir, "etopo5_nw_europe_5min.nc");
  EstimateBox[] = RegionGBIreland[];
  Call EstimateTriangles;
  If (!Quiet)
    Printf("estimate: %.0f triangles over %.0f km^2 of water (paper, Figure 8: 17,154-19,514)",
           EstimatedTriangles, EstimatedWaterArea / 1e6);
  EndIf
EndIf

If (DoMesh)
  Mesh 2;
  Assert(Mesh.NbTriangles > 14000 && Mesh.NbTriangles < 24000);
  Save "gb_ireland.msh";
EndIf
