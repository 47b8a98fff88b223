// A Region polygon drawn from headland to headland (docs/coastlines.md §4): the Irish Sea
// between St George's Channel (edge 9, Carnsore Point to St David's Head) and the North
// Channel (edge 5, the Rhins of Galloway to Torr Head), the other edges over land. GSHHG
// full (data/gshhg/gb_ireland_f.txt) at gamma = 2 km: exactly the two open boundaries the
// polygon draws; the edges also graze the shore at Loch Ryan's head and St David's Head,
// where the crossings shorter than gamma are joined into the coast instead (reported).
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "2000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../../data/gshhg/gb_ireland_f.txt";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-5.27, 51.89, -2.2, 52.2, -2.2, 55.3, -4.5, 55.1, -5.0, 54.90,
                       -6.10, 55.17, -7.5, 54.5, -7.5, 52.5, -6.45, 52.22};
Coastline[1].SeaAt = {-5.4, 53.35};
loops[] = Coastline{1};
open[] = Coastline{1, "OpenCurves"};
south[] = Coastline{1, "OpenCurves", "Edge9"};
north[] = Coastline{1, "OpenCurves", "Edge5"};
west[] = Coastline{1, "OpenCurves", "Edge7"};
shore[] = Coastline{1, "CoastPoints"};
all[] = Coastline{1, "Points"};
Printf("%g open curves: %g along edge 9, %g along edge 5, %g along edge 7", #open[], #south[], #north[], #west[]);
Printf("St George's Channel is not the North Channel: %g", south[0] != north[0]);
// Every point but the open curves' own interior points is a coast point.
Printf("coast points fewer than all points: %g", #shore[] < #all[]);
// expect: 2 open curves: 1 along edge 9, 1 along edge 5, 0 along edge 7
// expect: St George's Channel is not the North Channel: 1
// expect: coast points fewer than all points: 1
