// stdlib/ocean_fields.geo: each criterion macro on real data (ETOPO5 5' around the Great
// Barrier Reef), the Min, the Gradation, the closing-piece filter and the triangle estimate.
// Values computed independently in Python (haversine/chord formulas, f1 from ncdump's
// z(150E, 15S) = -1856 as in tests/scripts/fields/bathymetry.geo).
// compare_with_gmsh: skip (stdlib search path, native fields)
Include "ocean_fields.geo";
Include "regions.geo";
Call EarthSphere;

// Shore proximity to one point at 150.5E 15S: the chord to 150E 15S is 53,702.855 m.
lon = 150.5; lat = -15; Call LonLatPoint;
ShorePoints[] = {LonLatPointTag};
Call ShoreProximity;
lon = 150; lat = -15; Call LonLatToXYZ;
Printf("%.3f", FieldValue(ShoreDistanceField, x, y, z));   // expect: 53702.855
// 30 km + 53.7/500 of the way to 200 km.
Printf("%.2f", FieldValue(ShoreField, x, y, z));   // expect: 48258.97

// A point on the box's edge is dropped from the shore points (a closing piece is sea).
lon = 142; lat = -15; Call LonLatPoint;
on_edge = LonLatPointTag;
ShorePoints[] = {on_edge, ShorePoints[0]};
ShoreBox[] = RegionGBR[];
Call ShoreProximity;
Printf("%g kept, the inner one: %g", #ShorePoints[], ShorePoints[0] != on_edge);   // expect: 1 kept, the inner one: 1

// f1 with the defaults: 25 km sqrt(4000 / 1856), inside the 25-500 km clamp.
lon = 150; lat = -15; Call LonLatToXYZ;
BathyFile = StrCat(BathyDir, "etopo5_gbr_5min.nc");
Call WaveLength;
Printf("%.1f %.1f", FieldValue(WaveCriterionField, x, y, z), FieldValue(WaveField, x, y, z));   // expect: 36701.3 36701.3
Call BathyHessian;
f2 = FieldValue(HessianField, x, y, z);
Assert(f2 >= HessianSizeMin && f2 <= HessianSizeMax, "Hessian size %g", f2);

// The Min reports the smallest criterion and which one it is.
OceanFields[] = {ShoreField, WaveField, HessianField};
Call OceanSize;
h = FieldValue(SizeField, x, y, z);
Assert(h == Min(FieldValue(ShoreField, x, y, z), Min(FieldValue(WaveField, x, y, z), f2)));
by = FieldArgmin(MinSizeField, x, y, z);
Printf("argmin is one of the criteria: %g", by == ShoreField || by == WaveField || by == HessianField);   // expect: argmin is one of the criteria: 1
Printf("background %g", SizeField == MinSizeField);   // expect: background 1

// With a gradation the result stays at or below the Min.
GradationRate = 0.2;
GradationResolution = 0.5;
GradationBox[] = RegionGBR[];
Call OceanSize;
Printf("gradation %g, below the Min: %g", SizeField != MinSizeField, FieldValue(SizeField, x, y, z) <= FieldValue(MinSizeField, x, y, z) + 1e-6);   // expect: gradation 1, below the Min: 1

// A constant 10 km size over the 1 x 1 degree cell 150-151E 16-15S (all deep water):
// area 11,914.476 km^2, 275.153 equilateral triangles.
SizeField = newf;
Field[SizeField] = MathEval;
Field[SizeField].F = "10000";
EstimateDepthField = newf;
Field[EstimateDepthField] = Bathymetry;
Field[EstimateDepthField].FileName = BathyFile;
EstimateBox[] = {150, 151, -16, -15};
EstimateStep = 0.25;
Call EstimateTriangles;
Printf("%.3f km^2, %.3f triangles", EstimatedWaterArea / 1e6, EstimatedTriangles);   // expect: 11914.476 km^2, 275.153 triangles
// The same with its south-west quarter on a finer grid: the same sum.
EstimateFineBox[] = {150, 150.5, -16, -15.5};
EstimateFineStep = 0.05;
Call EstimateTriangles;
Printf("%.3f triangles", EstimatedTriangles);   // expect: 275.153 triangles
