// A small ocean basin on the unit PolarSphere: coastline points in stereographic
// (u,v), a B-spline coast, an island, size fields from distance to the shore.
R = 6371e3;
lc_far = 2e5; lc_coast = 2e4;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
n = 24;
For i In {0:n-1}
  t = 2*Pi*i/n;
  r = 0.30 + 0.04*Sin(3*t);
  Point(10+i) = {r*Cos(t), r*Sin(t), 0, lc_coast};
EndFor
BSpline(1) = {10:10+n-1, 10};
Line Loop(1) = {1};
For i In {0:7}
  t = 2*Pi*i/8;
  Point(100+i) = {0.05 + 0.03*Cos(t), 0.02 + 0.03*Sin(t), 0};
EndFor
Spline(2) = {100:107, 100};
Curve Loop(2) = {-2};
Plane Surface(1) = {1, 2};
Physical Curve("coast") = {1, 2};
Physical Surface("sea", 10) = {1};
Field[1] = Distance;
Field[1].NodesList = {10:10+n-1};
Field[1].CurvesList = {1, 2};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].IField = 1;
Field[2].LcMin = lc_coast;
Field[2].LcMax = lc_far;
Field[2].DistMin = 5e4;
Field[2].DistMax = 5e5;
Field[3] = MathEval;
Field[3].F = Sprintf("%g * (1 + 0.5 * Sin(x / %g))", lc_far, R);
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.Algorithm = 6;
Mesh.MshFileVersion = 2.2;
