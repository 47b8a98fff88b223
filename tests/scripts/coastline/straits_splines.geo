// Strait and spline options on gb_ireland_f.txt at 15 km. CloseStraits = 1 merges islands
// across straits narrower than MinStraitsFactor * gamma (Anglesey joins Great Britain
// across the Menai Strait); CheckSplines = 1 (the default) puts points back where two
// B-splines cross or touch, 0 turns it off (docs/coastlines.md section 6): at 15 km they
// do not cross, so both give the same control points.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "15000";
For c In {1 : 3}
  Coastline[c] = LonLatText;
  Coastline[c].FileName = "../../../data/gshhg/gb_ireland_f.txt";
  Coastline[c].AccuracyField = 1;
EndFor
Coastline[2].CloseStraits = 1;
Coastline[2].MinStraitsFactor = 1;
Coastline[1].CheckSplines = 0;
Coastline[3].CheckSplines = 1;
plain[] = Coastline{1};
closed[] = Coastline{2};
checked[] = Coastline{3};
p1[] = Coastline{1, "Points"};
p3[] = Coastline{3, "Points"};
Printf("closing straits merges islands: %g", #closed[] < #plain[]);
Printf("checked splines: same loops %g, same points %g", #checked[] == #plain[], #p3[] == #p1[]);
// expect: closing straits merges islands: 1
// expect: checked splines: same loops 1, same points 1
// GSHHG 2.3.7: 17 loops, 9 with closed straits; the former span-hull check gave 3,714
// control points instead of 859.
