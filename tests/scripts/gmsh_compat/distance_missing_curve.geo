// A Distance field listing a curve and a point that do not exist: Gmsh skips them
// (benchmarks/2d_large/mediterranean.geo lists curves it has split or deleted); so do we,
// with a warning at the option, and the field measures the distance to the others.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].CurvesList = {1, 99};
Field[1].PointsList = {42};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 0.05;
Field[2].SizeMax = 0.3;
Field[2].DistMin = 0.1;
Field[2].DistMax = 0.5;
Background Field = 2;
Mesh 2;
// Finer along curve 1 (y = 0) than along curve 3 (y = 1): the field saw curve 1.
Printf("%g", Mesh.NbTriangles > 100);  // expect: 1
// expect warning: 9:1: gmsh-compat: Field[1].CurvesList lists Curve 99, which does not exist: Gmsh skips it, and so do we
// expect warning: 10:1: gmsh-compat: Field[1].PointsList lists Point 42, which does not exist: Gmsh skips it, and so do we
