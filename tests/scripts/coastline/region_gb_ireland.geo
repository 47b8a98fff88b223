// Region clipping with open boundaries: gb_ireland_f.txt cut to {-8, 0, 50, 56} at 5 km.
// Great Britain and Ireland leave the box, so the cut coasts are closed along the box by
// open-boundary curves, returned by Coastline{n, "OpenCurves"} for Physical Curve("open");
// the water outer loops alternate coast pieces and box pieces. Great Britain cuts the box
// into several seas, each its own surface: Coastline{n, "LoopsPerSurface"} says how many of
// the returned loops (outer first, then holes) belong to each.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/gb_ireland_f.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-8, 0, 50, 56};
loops[] = Coastline{1};
outer[] = Coastline{1, "Outer"};
open[] = Coastline{1, "OpenCurves"};
curves[] = Coastline{1, "Curves"};
k[] = Coastline{1, "LoopsPerSurface"};
first = 0;
For s In {0 : #k[] - 1}
  If (loops[first] != outer[s])
    Error("surface %g: its outer loop does not come first", s);
  EndIf
  Plane Surface(s + 1) = loops[{first : first + k[s] - 1}];
  first += k[s];
EndFor
Physical Curve("open") = open[];
Physical Surface("sea") = Surface{:};
b[] = CombinedBoundary{ Surface{:}; };
Printf("%g seas, every loop in one: %g", #outer[], first == #loops[]);
Printf("open curves and coast pieces: %g", #open[] >= 3 && #curves[] > #open[]);
Printf("boundary of the seas = all curves: %g", #b[] == #curves[]);
// Every open curve lies on the box: its end points have lon -8 or 0, or lat 50 or 56.
onbox = 1;
For i In {0 : #open[] - 1}
  e[] = Boundary{ Curve{open[i]}; };
  For j In {0 : 1}
    x[] = Point{e[j]};
    lon = Atan2(x[1], x[0]) * 180 / Pi;
    lat = Asin(x[2] / R) * 180 / Pi;
    d = Fabs(lon + 8);
    d = Fabs(lon) < d ? Fabs(lon) : d;
    d = Fabs(lat - 50) < d ? Fabs(lat - 50) : d;
    d = Fabs(lat - 56) < d ? Fabs(lat - 56) : d;
    If (d > 1e-6)
      onbox = 0;
    EndIf
  EndFor
EndFor
Printf("open curves end on the box: %g", onbox);
// 5 seas (the Channel, the Irish and Celtic Seas west of Britain, and three pieces of the
// North Sea and the Minch cut off by the box), 15 open curves, 39 curves in 14 loops.
// expect: 5 seas, every loop in one: 1
// expect: open curves and coast pieces: 1
// expect: boundary of the seas = all curves: 1
// expect: open curves end on the box: 1
