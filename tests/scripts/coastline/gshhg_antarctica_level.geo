// AntarcticaLevel chooses Antarctica's outline in GSHHG >= 2.3 (level 5 ice front, the
// default; 6 grounding line; 0 none). Without a Region, Antarctica's ring round the South
// Pole is the ocean's outer loop: with none kept there is no outer loop at all, and the
// land rings come back as holes with no surface (docs/interpreter.md, "Order").
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
levels[] = {5, 6, 0};
For c In {1 : 3}
  Coastline[c] = GSHHG;
  Coastline[c].Resolution = "c";
  Coastline[c].AccuracyField = 1;
  Coastline[c].AntarcticaLevel = levels[c - 1];
  outer[] = Coastline{c, "Outer"};
  loops[] = Coastline{c};
  Printf("AntarcticaLevel %g: %g outer loop(s), %g loops", levels[c - 1], #outer[], #loops[]);
EndFor
// expect: AntarcticaLevel 5: 1 outer loop(s), 76 loops
// expect: AntarcticaLevel 6: 1 outer loop(s), 79 loops
// expect: AntarcticaLevel 0: 0 outer loop(s), 75 loops
