// The tutorial's model (docs/tutorial.md): the Irish Sea, from nothing to a regional ocean
// mesh with the stdlib templates. 2 km on the coasts to 15 km at 100 km from them; the
// coastline kept at the 2 km accuracy; the box's sides are the "open" boundary.
//   stereomesh -0 examples/irish_sea.geo          (evaluate and check)
//   stereomesh -1 examples/irish_sea.geo -o irish_sea.msh   (1D mesh of the coasts)
DefineConstant[ CoastSize = 2e3, FarSize = 15e3, Reach = 100e3 ];
DefineConstant[ ShoreSizeMin = CoastSize, ShoreSizeMax = FarSize, ShoreDistMax = Reach ];
Include "earth.geo";
Include "ocean_fields.geo";

// 1. The Earth: a sphere of radius 6371 km, meshed in its stereographic plane.
Call EarthSphere;

// 2. The coastline: GSHHG full resolution, cut to a lon/lat box, coarsened to CoastSize.
box[] = {-7, -2.5, 51.5, 55.5};
Field[1] = MathEval;
Field[1].F = Sprintf("%g", CoastSize);
Coastline[1] = LonLatText;
Coastline[1].FileName = StrCat(GshhgDir, "gb_ireland_f.txt");
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {box[]};

// 3. The sea surface(s) and the physical groups a model needs.
OceanLoops[] = Coastline{1};
OceanLoopsPerSurface[] = Coastline{1, "LoopsPerSurface"};
Call OceanSurfaces;
open[] = Coastline{1, "OpenCurves"};
coast[] = Coastline{1, "Curves"};
coast[] -= open[];
Physical Surface("sea") = {OceanSurfaces[]};
Physical Curve("coast") = {coast[]};
Physical Curve("open") = {open[]};

// 4. The size field: shore proximity, measured to the coast's points (not the box's).
ShorePoints[] = Coastline{1, "Points"};
ShoreBox[] = box[];
Call ShoreProximity;
OceanFields[] = {ShoreField};
Call OceanSize;

// 5. Check before meshing: the size mid-channel between Dublin and Holyhead.
lon = -5.4;  lat = 53.35;
Call LonLatToXYZ;
h = FieldValue(SizeField, x, y, z);
Printf("%g sea(s), %g islands, %g open-boundary curves; mid-channel size %.1f km",
       #OceanSurfaces[], #OceanLoops[] - #OceanSurfaces[], #open[], h / Km);
Assert(h > CoastSize && h <= FarSize, "mid-channel size %g m", h);

// 6. The mesh: `stereomesh -2 examples/irish_sea.geo -o irish_sea.msh`, or, in the script,
//    Mesh 2; Save "irish_sea.msh";  (once stereomesh has Mesh 2)
