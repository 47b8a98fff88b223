// Mesh.ElementsAcrossChannels (default 2): the ChannelWidth of every imported coastline
// inside the Min of the size, on the surfaces the coastline bounds. Two square islands
// 0.1 degrees (11 km) apart in a box, sized 20 km: without the criterion the strait is one
// triangle across; with N = 2 the strait's coasts get edges of about 5.6 km.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371e3;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "20e3";
Field[2] = MathEval;   // the coast's accuracy: the criterion never goes below it
Field[2].F = "2e3";
Coastline[1] = Loops2;
Coastline[1].FileName = "../../data/field/strait_loops2.txt";
Coastline[1].AccuracyField = 2;
Coastline[1].CurveType = "Line";
Coastline[1].Region = {-0.5, 1.6, -0.5, 1.0};
loops[] = Coastline{1};
Plane Surface(1) = loops[];
Background Field = 1;
Printf("default %g", Mesh.ElementsAcrossChannels);   // expect: default 2
Mesh.ElementsAcrossChannels = 0;
Mesh 1;
off = Mesh.NbNodes;
Mesh.ElementsAcrossChannels = 2;
Mesh 1;
on = Mesh.NbNodes;
// The two facing sides (55 km each) at 5.6 km instead of 20 km: about 2 x 7 more nodes.
Printf("more coast nodes: %g", on - off >= 10 && on - off <= 30);   // expect: more coast nodes: 1
Mesh.ElementsAcrossChannels = 4;
Mesh 1;
Printf("more with 4: %g", Mesh.NbNodes > on);   // expect: more with 4: 1
// With the accuracy at 20 km the strait (11 km) is narrower than the coast is drawn: no
// refinement for it.
Field[2].F = "20e3";
Mesh 1;
Printf("none below the accuracy: %g", Mesh.NbNodes == off);   // expect: none below the accuracy: 1
Mesh 2;
Printf("meshed: %g", Mesh.NbTriangles > 0);     // expect: meshed: 1
