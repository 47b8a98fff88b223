// Gmsh 2.x loops2 text (tests/data/coast_scripts/islands_loops2.txt: Islay, Anglesey and the
// Isle of Man from GSHHG 2.3.7 full, lonlat_degrees) at gamma = 2 km. Without Antarctica
// or a region there is no outer loop: the three islands come back as holes with no
// surface (Outer is empty) for the script to bound. With a Region the box becomes the
// outer loop, made of open-boundary curves.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "2000";
Coastline[1] = Loops2;
Coastline[1].FileName = "../../data/coast_scripts/islands_loops2.txt";
Coastline[1].Coordinate = "lonlat_degrees";
Coastline[1].AccuracyField = 1;
islands[] = Coastline{1};
outer[] = Coastline{1, "Outer"};
n[] = Coastline{1, "ControlPoints"};
Printf("%g islands, %g outer loops", #islands[], #outer[]);
// Control points near the island's perimeter / 2 km: Islay about 65, Anglesey 60, Man 45.
For i In {0 : 2}
  Printf("island %g: between 20 and 120 points: %g", i + 1, n[i] >= 20 && n[i] <= 120);
EndFor
// The same islands in a box: the box is the ocean's outer loop, its sides open curves.
Coastline[2] = Loops2;
Coastline[2].FileName = "../../data/coast_scripts/islands_loops2.txt";
Coastline[2].AccuracyField = 1;
Coastline[2].Region = {-7, -3.5, 53, 56.5};
loops[] = Coastline{2};
open[] = Coastline{2, "OpenCurves"};
outer[] = Coastline{2, "Outer"};
Printf("%g loops, outer first: %g, open curves: %g", #loops[], outer[0] == loops[0], #open[] > 0);
Plane Surface(1) = loops[];
Physical Curve("open") = open[];
Physical Surface("sea") = {1};
// expect: 3 islands, 0 outer loops
// expect: island 1: between 20 and 120 points: 1
// expect: island 2: between 20 and 120 points: 1
// expect: island 3: between 20 and 120 points: 1
// expect: 4 loops, outer first: 1, open curves: 1
