// MinChannelWidth means what it says (KeepPassages = 0): the Cymyran Strait between Holy
// Island and Anglesey (4.564W 53.263N, 30.6 m wide in GSHHG full) at a 2 km accuracy. Its
// 2 km segments made no clean cut at the 30 m pinch, so it was left open; the original
// points near a refused cut are now put back and the place tried again: the strait is
// closed (Holy Island joins Anglesey) and no coast point is left along it. With
// KeepPassages = 1 (Coastline 3) only water that ends is filled: the strait, a passage
// between two waters, stays open as without MinChannelWidth.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "2000";
For c In {1 : 3}
  Coastline[c] = LonLatText;
  Coastline[c].FileName = "../../../data/gshhg/gb_ireland_f.txt";
  Coastline[c].AccuracyField = 1;
  Coastline[c].Region = {-5, -4, 53, 53.5};
  Coastline[c].SeaAt = {-4.8, 53.3};
EndFor
Coastline[2].MinChannelWidth = 2000;
Coastline[3].MinChannelWidth = 2000;
Coastline[3].KeepPassages = 1;
For c In {1 : 3}
  pts[] = Coastline{c, "Points"};
  strait = 0;
  For i In {0 : #pts[] - 1}
    p[] = Point{pts[i]};
    lon = Atan2(p[1], p[0]) * 180 / Pi;
    lat = Atan2(p[2], Hypot(p[0], p[1])) * 180 / Pi;
    strait += lon > -4.58 && lon < -4.55 && lat > 53.25 && lat < 53.28;
  EndFor
  cl[] = Coastline{c, "Closures"};
  near = 0;
  For i In {0 : #cl[] - 1 : 3}
    near += Fabs(cl[i] + 4.566) < 0.02 && Fabs(cl[i + 1] - 53.262) < 0.02;
  EndFor
  Printf("Coastline %g: %g coast points along the strait, %g closure(s) there", c, strait, near);
EndFor
// expect: Coastline 1: 2 coast points along the strait, 0 closure(s) there
// expect: Coastline 2: 0 coast points along the strait, 1 closure(s) there
// expect: Coastline 3: 2 coast points along the strait, 0 closure(s) there
