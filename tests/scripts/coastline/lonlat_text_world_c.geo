// GMT lon/lat text (world_c.txt, GSHHG 2.3.7 crude) at gamma = 100 km with a space-varying
// accuracy from 25 km at the North Pole to 100 km at the South Pole (a size field
// evaluated at 3D points in metres). MinArea drops islands below 500 km^2; CurveType "Line" makes each loop one
// closed polyline instead of a BSpline.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = Sprintf("25e3 + 37.5e3 * (1 - z / %.17g)", R);
Coastline[2] = LonLatText;
Coastline[2].FileName = "../../../data/gshhg/world_c.txt";
Coastline[2].AccuracyField = 1;
Coastline[2].MinArea = 500;
Coastline[2].CurveType = "Line";
loops[] = Coastline{2};
n[] = Coastline{2, "ControlPoints"};
pts[] = Coastline{2, "Points"};
curves[] = Coastline{2, "Curves"};
Plane Surface(1) = loops[];
// The same file without the finer north and without MinArea.
Field[2] = MathEval;
Field[2].F = "100e3";
Coastline[3] = LonLatText;
Coastline[3].FileName = "../../../data/gshhg/world_c.txt";
Coastline[3].AccuracyField = 2;
coarse[] = Coastline{3};
cpts[] = Coastline{3, "Points"};
// MinArea alone, at the uniform 100 km (which keeps islands of a few thousand km^2).
Coastline[4] = LonLatText;
Coastline[4].FileName = "../../../data/gshhg/world_c.txt";
Coastline[4].AccuracyField = 2;
Coastline[4].MinArea = 20000;   // Jamaica (11,000 km^2) and smaller go
big[] = Coastline{4};
// GSHHG 2.3.7 crude: 177 loops / 4,080 points (fine north, MinArea), 76 / 1,967 (uniform),
// the uniform import with MinArea keeps fewer loops than without.
Printf("one polyline per loop: %g", #curves[] == #loops[]);
Printf("finer north gives more points: %g", #pts[] > 1.5 * #cpts[]);
Printf("MinArea drops islands: %g", #big[] < #coarse[]);
Printf("loops between 150 and 200: %g, uniform between 65 and 90: %g", #loops[] >= 150 && #loops[] <= 200,
       #coarse[] >= 65 && #coarse[] <= 90);
// expect: one polyline per loop: 1
// expect: finer north gives more points: 1
// expect: MinArea drops islands: 1
// expect: loops between 150 and 200: 1, uniform between 65 and 90: 1
