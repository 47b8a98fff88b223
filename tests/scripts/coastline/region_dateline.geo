// A region across the dateline: {160, 200, -50, -30} (longitudes past 180 are fine, there is
// no seam) around New Zealand, from GSHHG 2.3.7 low (world_l.txt) at 10 km. The box holds all
// of New Zealand and the Chatham Islands at 176.5W (183.5E) and cuts no coast, so its four
// sides form one open curve: the outer loop.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/world_l.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {160, 200, -50, -30};
loops[] = Coastline{1};
outer[] = Coastline{1, "Outer"};
open[] = Coastline{1, "OpenCurves"};
pts[] = Coastline{1, "Points"};
Plane Surface(1) = loops[];
// Control points of the Chatham Islands (east of the dateline) and of New Zealand (west).
chatham = 0;
nz = 0;
For i In {0 : #pts[] - 1}
  x[] = Point{pts[i]};
  lon = Atan2(x[1], x[0]) * 180 / Pi;
  lat = Asin(x[2] / R) * 180 / Pi;
  If (lon > -177 && lon < -176 && lat > -44.5 && lat < -43.5)
    chatham += 1;
  EndIf
  If (lon > 166 && lon < 179 && lat > -47.5 && lat < -34)
    nz += 1;
  EndIf
EndFor
Printf("%g surface, outer first: %g, one open curve: %g", #outer[], outer[0] == loops[0], #open[] == 1);
Printf("Chatham Islands east of the dateline: %g, New Zealand: %g", chatham >= 5, nz >= 200);
// 12 loops (the box and 11 islands); 10 control points on the Chatham Islands, 343 on New
// Zealand.
// expect: 1 surface, outer first: 1, one open curve: 1
// expect: Chatham Islands east of the dateline: 1, New Zealand: 1
