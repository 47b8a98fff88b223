// GSHHG crude straight from the system's binned file (Debian gmt-gshhg-low) imports as
// the text export of the same data (data/gshhg/world_c.txt, made by gmt coast): the
// same loops and control points at gamma = 100 km.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
Coastline[1] = GSHHG;
Coastline[1].Resolution = "c";
Coastline[1].AccuracyField = 1;
a[] = Coastline{1};
na[] = Coastline{1, "ControlPoints"};
Coastline[2] = LonLatText;
Coastline[2].FileName = "../../../data/gshhg/world_c.txt";
Coastline[2].AccuracyField = 1;
b[] = Coastline{2};
nb[] = Coastline{2, "ControlPoints"};
Printf("loops %g, same as the text: %g", #a[], #a[] == #b[]);
Printf("same control points: %g", #na[] == #nb[]);
// expect: loops 76, same as the text: 1
// expect: same control points: 1
