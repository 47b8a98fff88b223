// Layers round a rectangular hole (0.4 x 0.2, meshed at 0.05: 24 edges), 3 layers
// (0.005, 0.0125, 0.02375 below 0.04), fans at two of its corners: at point 6 six
// elements per half turn, over its quarter turn 3 (4 slots), at point 7 four (2, so 3
// slots); each slot a triangle at the corner and 2 quadrangles above it. So 24 * 3 + 4 * 2
// + 3 * 2 = 86 quadrangles. `gmsh -2`: 86 quadrangles, 358 triangles.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.2}; Point(2) = {2, 0, 0, 0.2};
Point(3) = {2, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Point(5) = {0.8, 0.4, 0, 0.05}; Point(6) = {1.2, 0.4, 0, 0.05};
Point(7) = {1.2, 0.6, 0, 0.05}; Point(8) = {0.8, 0.6, 0, 0.05};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {5, 6, 7, 8};
Field[1].Size = 0.005;
Field[1].Ratio = 1.5;
Field[1].Thickness = 0.04;
Field[1].FanPointsList = {6, 7};
Field[1].FanPointsSizesList = {6, 4};
Field[1].Quads = 1;
BoundaryLayer Field = 1;
Mesh 2;
Printf("%g", Mesh.NbQuadrangles);   // expect: 86
Printf("%g", Fabs(Mesh.NbTriangles - 358) <= 0.15 * 358);   // expect: 1
