// The Mediterranean from world_i_A100.txt in a box from Gibraltar (5.6W) at a coarse 5 km
// accuracy. MinChannelWidth = 2 km closes the Suez Canal (215 m in the data, at 30.64N),
// the Bosporus (1.3 km) and the Dardanelles (1.9 km), and keeps Gibraltar (14 km): with
// SeaAt in the Ionian Sea only the Mediterranean stays, and its one open boundary is the
// West side at Gibraltar (the Gulfs of Suez and Aqaba, the Black Sea and the Bay of Biscay,
// which the box also cuts, are other seas). At 500 m the Bosporus and the Dardanelles stay
// open and the Black Sea comes with the Mediterranean: open curves on the East and North.
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
EndFor
Coastline[1].MinChannelWidth = 2000;
Coastline[2].MinChannelWidth = 500;
Coastline[3].Dams = {32.2, 30.9, 32.45, 30.9};   // across the canal near 30.9N, by hand
For c In {1 : 3}
  Printf("Coastline %g: %g sea(s); open curves W %g, E %g, S %g, N %g", c, #Coastline{c, "Outer"},
         #Coastline{c, "OpenCurves", "West"}, #Coastline{c, "OpenCurves", "East"},
         #Coastline{c, "OpenCurves", "South"}, #Coastline{c, "OpenCurves", "North"});
EndFor
// expect: Coastline 1: 1 sea(s); open curves W 1, E 0, S 0, N 0
// expect: Coastline 2: 1 sea(s); open curves W 1, E 2, S 0, N 4
// expect: Coastline 3: 1 sea(s); open curves W 1, E 2, S 0, N 4
// The canal south of the dams is no longer sea: no coast point left in it.
For c In {1 : 3}
  inside = 0;
  pts[] = Coastline{c, "Points"};
  For i In {0 : #pts[] - 1}
    p[] = Point{pts[i]};
    lon = Atan2(p[1], p[0]) * 180 / Pi;
    lat = Atan2(p[2], Hypot(p[0], p[1])) * 180 / Pi;
    inside += lon > 32.2 && lon < 32.7 && lat > 29.5 && lat < 30.6;
  EndFor
  Printf("Coastline %g: %g points in the canal south of 30.6N", c, inside);
EndFor
// expect: Coastline 1: 0 points in the canal south of 30.6N
// expect: Coastline 2: 0 points in the canal south of 30.6N
// expect: Coastline 3: 0 points in the canal south of 30.6N
s[] = Coastline{1, "Surfaces"};
coast[] = Coastline{1, "CoastCurves"};
Printf("%g surface, %g coast + %g open = %g curves", #s[], #coast[], #Coastline{1, "OpenCurves"},
       #Coastline{1, "Curves"});
// expect: 1 surface, 110 coast + 1 open = 111 curves
