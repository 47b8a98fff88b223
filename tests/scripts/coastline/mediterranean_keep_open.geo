// KeepOpen on real data: the Mediterranean of mediterranean_passages.geo (world_i_A100.txt,
// 5 km accuracy, MinChannelWidth = 2 km, SeaAt in the Ionian Sea). Without KeepOpen the
// Bosporus (1275 m here) and the Dardanelles (1861 m) are closed, and the Sea of Marmara
// and the Black Sea are dropped. KeepOpen at a point of each keeps both straits open: the
// Black Sea comes with the Mediterranean (open curves on the East and North, as with
// MinChannelWidth = 500 m). Closures and DroppedSeas list the rest with places and figures.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "5000";
For c In {1 : 3}
  Coastline[c] = LonLatText;
  Coastline[c].FileName = "../../../data/gshhg/world_i_A100.txt";
  Coastline[c].AccuracyField = 1;
  Coastline[c].Region = {-5.6, 37, 29, 46.5};
  Coastline[c].SeaAt = {18, 35};
  Coastline[c].MinChannelWidth = 2000;
EndFor
Coastline[2].KeepOpen = {29.08, 41.12};                // the Bosporus only
Coastline[3].KeepOpen = {29.08, 41.12, 26.40, 40.20};  // and the Dardanelles
For c In {1 : 3}
  cl[] = Coastline{c, "Closures"};
  ds[] = Coastline{c, "DroppedSeas"};
  bosporus = 0; dardanelles = 0; largest = 0;
  For i In {0 : #cl[] - 1 : 3}
    bosporus += cl[i] > 28.9 && cl[i] < 29.2 && cl[i + 1] > 40.95 && cl[i + 1] < 41.25;
    dardanelles += cl[i] > 26.1 && cl[i] < 26.7 && cl[i + 1] > 40.0 && cl[i + 1] < 40.5;
  EndFor
  For i In {0 : #ds[] - 1 : 3}
    largest = Max(largest, ds[i + 2]);
  EndFor
  Printf("Coastline %g: %g closures (Bosporus %g, Dardanelles %g), %g seas dropped, largest %.0f km^2; open E %g N %g",
         c, #cl[] / 3, bosporus, dardanelles, #ds[] / 3, largest, #Coastline{c, "OpenCurves", "East"},
         #Coastline{c, "OpenCurves", "North"});
EndFor
// The largest sea dropped (the Black Sea; with the Sea of Marmara in 2): 1 km^2 more before
// the wedge between a dam and the coast near 27.45E 42.44N became land (passages.cpp,
// trim_dam_wedges).
// expect: Coastline 1: 22 closures (Bosporus 1, Dardanelles 1), 19 seas dropped, largest 322655 km^2; open E 0 N 0
// expect: Coastline 2: 21 closures (Bosporus 0, Dardanelles 1), 18 seas dropped, largest 334098 km^2; open E 0 N 0
// expect: Coastline 3: 20 closures (Bosporus 0, Dardanelles 0), 17 seas dropped, largest 117195 km^2; open E 2 N 4
