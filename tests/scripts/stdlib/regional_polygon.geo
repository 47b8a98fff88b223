// RegionalSea with a Region polygon (docs/coastlines.md §4, "Polygons"): the Irish Sea
// between St George's Channel and the North Channel on the full-resolution GSHHG export at
// 2 km, the polygon's edges crossing water only at the two channels, so exactly 2 open
// curves. RegionalShorePoints[] are then the coast curves' points ("CoastPoints"): none of
// them lies inside an open curve, and ShoreProximity takes them without a ShoreBox[].
// compare_with_gmsh: skip (native Coastline statements)
Include "earth.geo";
Include "ocean_fields.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(GshhgDir, "gb_ireland_f.txt");
RegionalBox[] = {-5.27, 51.89, -2.2, 52.2, -2.2, 55.3, -4.5, 55.1, -5.0, 54.90,
                 -6.10, 55.17, -7.5, 54.5, -7.5, 52.5, -6.45, 52.22};
RegionalAccuracy = 2e3;
RegionalSeaAt[] = {-5.4, 53.35};
Call RegionalSea;
Printf("%g sea, %g open curves", #RegionalSurfaces[], #RegionalOpenCurves[]);
// expect: 1 sea, 2 open curves
coast_points_[] = Coastline{1, "CoastPoints"};
Printf("%g shore points, %g not CoastPoints, %g fewer than Points", #RegionalShorePoints[],
       #Unique({RegionalShorePoints[], coast_points_[]}) - #coast_points_[],
       #Coastline{1, "Points"} - #RegionalShorePoints[]);
// expect: 1136 shore points, 0 not CoastPoints, 23 fewer than Points
ShorePoints[] = RegionalShorePoints[];
ShoreSizeMin = 2e3;
ShoreSizeMax = 15e3;
ShoreDistMax = 100e3;
Call ShoreProximity;
// The North Channel's open boundary half-way across (the great circle from 5.0W 54.90N to
// 6.10W 55.17N): the coast is about 10 km away on either side; with the open curves' points
// among the shore points (Coastline's "Points") it is 1 km.
lon = -5.55;  lat = 55.036;
Call LonLatToXYZ;
Printf("%.0f km", FieldValue(ShoreDistanceField, x, y, z) / 1e3);
// expect: 24 km
