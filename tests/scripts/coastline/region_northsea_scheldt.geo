// A file with open coast pieces and no Region: northsea_scheldt_f.txt (GSHHG 2.3.7 full, cut
// by GMT to -4/9/48/58) is closed along its own -R box, at a finer accuracy near the
// Scheldt estuary (51.4N 4E): gamma = 1 km there growing to 20 km (a Threshold on the
// distance to a point, in metres on the Earth-sized sphere).
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Euclidean Coordinates;
lon = 4 * Pi / 180;  lat = 51.4 * Pi / 180;
Point(3) = {R * Cos(lat) * Cos(lon), R * Cos(lat) * Sin(lon), R * Sin(lat)};
Coordinates Surface 1;
Field[1] = Distance;
Field[1].PointsList = {3};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 1000;
Field[2].SizeMax = 20000;
Field[2].DistMin = 20000;
Field[2].DistMax = 400000;
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/northsea_scheldt_f.txt";
Coastline[1].AccuracyField = 2;
loops[] = Coastline{1};
outer[] = Coastline{1, "Outer"};
k[] = Coastline{1, "LoopsPerSurface"};
open[] = Coastline{1, "OpenCurves"};
first = 0;
For s In {0 : #k[] - 1}
  Plane Surface(news) = loops[{first : first + k[s] - 1}];
  first += k[s];
EndFor
Physical Curve("open") = open[];
pts[] = Coastline{1, "Points"};
// The same file at a uniform 20 km: far fewer control points and loops.
Field[3] = MathEval;
Field[3].F = "20000";
Coastline[2] = LonLatText;
Coastline[2].FileName = "../../../data/gshhg/northsea_scheldt_f.txt";
Coastline[2].AccuracyField = 3;
coarse[] = Coastline{2};
cpts[] = Coastline{2, "Points"};
Printf("every loop in a surface: %g, open curves: %g", first == #loops[], #open[] >= 2);
Printf("finer near the Scheldt: %g more points, %g more loops", #pts[] > 2 * #cpts[], #loops[] > #coarse[]);
// 3 seas (the North Sea, and two pieces of the Irish Sea west of Britain cut off by the box at
// 4W), 15 open curves, 10 loops and 792 control points, against 5 loops and 323 at 20 km.
Printf("%g seas", #outer[]);
// expect: every loop in a surface: 1, open curves: 1
// expect: finer near the Scheldt: 1 more points, 1 more loops
// expect: 3 seas
