// The original GSHHS binary (gshhs_c.b, GSHHG 2.3 crude) imported on the Earth-sized
// PolarSphere at gamma = 200 km, levels {1} plus Antarctica's ice front (level 5): the
// loop round the South Pole (Antarctica) is the outer loop of the ocean, every other
// kept polygon one of its holes, each a closed BSpline.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "200e3";
Coastline[1] = GSHHS;
Coastline[1].FileName = "../../../data/gshhs/gshhs_c.b";
Coastline[1].Levels = {1};
Coastline[1].AccuracyField = 1;
Coastline[1].DeviationFactor = 0;   // the coarsening's control points (no data point put back)
loops[] = Coastline{1};
outer[] = Coastline{1, "Outer"};
curves[] = Coastline{1, "Curves"};
open[] = Coastline{1, "OpenCurves"};
pts[] = Coastline{1, "Points"};
Printf("%g outer loop, first returned: %g, open curves: %g", #outer[], outer[0] == loops[0], #open[]);
Printf("one curve per loop: %g", #curves[] == #loops[]);
// Antarctica: the outer loop's first point lies south of 60S (z < -R sin 60).
p[] = Point{pts[0]};
Printf("outer loop in the south: %g", p[2] < -R * Sin(60 * Pi / 180));
// The islands are holes of one ocean surface; the model accepts them all.
Plane Surface(1) = loops[];
b[] = Boundary{ Surface{1}; };
Printf("surface boundary curves = loops: %g", #b[] == #loops[]);
// 39 islands and 929 control points in all with GSHHG 2.3.7 crude (the range allows kernel tuning).
Printf("islands between 33 and 45: %g", #loops[] - 1 >= 33 && #loops[] - 1 <= 45);
Printf("points between 790 and 1070: %g", #pts[] >= 790 && #pts[] <= 1070);
// Levels {1, 2}: lakes are water too, each the outer loop of a surface of its own (with
// level-3 islands kept they would be its holes). GSHHG 2.3 crude at 200 km: the ocean
// with its 39 islands, then 25 lakes (the Caspian Sea, the Great Lakes, ...).
Coastline[2] = GSHHS;
Coastline[2].FileName = "../../../data/gshhs/gshhs_c.b";
Coastline[2].Levels = {1, 2};
Coastline[2].AccuracyField = 1;
all[] = Coastline{2};
outer2[] = Coastline{2, "Outer"};
k[] = Coastline{2, "LoopsPerSurface"};
first = 0;
For i In {0 : #k[] - 1}
  Plane Surface(news) = all[{first : first + k[i] - 1}];
  first += k[i];
EndFor
Printf("ocean first with the same islands: %g, lakes between 15 and 35: %g", k[0] == #loops[],
       #outer2[] - 1 >= 15 && #outer2[] - 1 <= 35);
// expect: 1 outer loop, first returned: 1, open curves: 0
// expect: one curve per loop: 1
// expect: outer loop in the south: 1
// expect: surface boundary curves = loops: 1
// expect: islands between 33 and 45: 1
// expect: points between 790 and 1070: 1
// expect: ocean first with the same islands: 1, lakes between 15 and 35: 1
