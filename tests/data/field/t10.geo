// Gmsh tutorial t10's geometry and field set, meshed by Gmsh 4.8.4 itself:
// `gmsh -2 -format msh22 t10.geo -o t10_gmsh.msh`; t10_gmsh_edges.txt keeps
// the midpoint and length of the edges of every 16th triangle of that mesh.
// unit_field compares those lengths with our Field[7] at the midpoints.
lc = .15;
Point(1) = {0.0,0.0,0,lc};
Point(2) = {1,0.0,0,lc};
Point(3) = {1,1,0,lc};
Point(4) = {0,1,0,lc};
Point(5) = {0.2,.5,0,lc};
Line(1) = {1,2};
Line(2) = {2,3};
Line(3) = {3,4};
Line(4) = {4,1};
Curve Loop(5) = {1,2,3,4};
Plane Surface(6) = {5};
Field[1] = Distance;
Field[1].PointsList = {5};
Field[1].CurvesList = {2};
Field[1].NumPointsPerCurve = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc / 30;
Field[2].SizeMax = lc;
Field[2].DistMin = 0.15;
Field[2].DistMax = 0.5;
Field[3] = MathEval;
Field[3].F = "Cos(4*3.14*x) * Sin(4*3.14*y) / 10 + 0.101";
Field[4] = Distance;
Field[4].CurvesList = {1};
Field[4].NumPointsPerCurve = 100;
Field[5] = MathEval;
Field[5].F = Sprintf("F4^3 + %g", lc / 10);
Field[6] = Box;
Field[6].VIn = lc / 15;
Field[6].VOut = lc;
Field[6].XMin = 0.3;
Field[6].XMax = 0.6;
Field[6].YMin = 0.3;
Field[6].YMax = 0.6;
Field[6].Thickness = 0.3;
Field[7] = Min;
Field[7].FieldsList = {2, 3, 5, 6};
Background Field = 7;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
