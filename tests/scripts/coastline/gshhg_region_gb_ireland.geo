// GSHHG full resolution in the box of the paper's Figure 5 (-11/2/49/61): only the
// polygons with a piece in the box's 1-degree bins are read, whole (Eurasia too), and the
// Region cuts them; the same loops and control points as the text export of the box
// (data/gshhg/gb_ireland_f.txt) at gamma = 15 km.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "15e3";
Coastline[1] = GSHHG;
Coastline[1].Resolution = "f";
Coastline[1].AccuracyField = 1;
Coastline[1].Region = {-11, 2, 49, 61};
a[] = Coastline{1};
na[] = Coastline{1, "ControlPoints"};
oa[] = Coastline{1, "OpenCurves"};
Coastline[2] = LonLatText;
Coastline[2].FileName = "../../../data/gshhg/gb_ireland_f.txt";
Coastline[2].AccuracyField = 1;
Coastline[2].Region = {-11, 2, 49, 61};
b[] = Coastline{2};
nb[] = Coastline{2, "ControlPoints"};
ob[] = Coastline{2, "OpenCurves"};
Printf("loops %g, same as the text: %g", #a[], #a[] == #b[]);
Printf("same control points: %g, same open curves: %g", #na[] == #nb[], #oa[] == #ob[]);
// expect: loops 17, same as the text: 1
// expect: same control points: 1, same open curves: 1
