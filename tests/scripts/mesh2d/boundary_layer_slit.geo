// Layers on both sides of an embedded line (20 edges at 0.05), with fans round both of
// its free ends: 4 layers (0.004, 0.0092, 0.01596, 0.0248 below 0.03) on 2 x 20 edges,
// and at each end a half turn of Mesh.BoundaryLayerFanElements = 5 elements (6 slots, each
// a triangle at the tip and 3 quadrangles): 160 + 2 x 18 = 196 quadrangles.
// `gmsh -2` of this script: 196 quadrangles, 1138 triangles.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.1}; Point(2) = {2, 0, 0, 0.1};
Point(3) = {2, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {0.5, 0.5, 0, 0.05}; Point(6) = {1.5, 0.5, 0, 0.05};
Line(5) = {5, 6};
Line {5} In Surface {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {5};
Field[1].Size = 0.004;
Field[1].Ratio = 1.3;
Field[1].Thickness = 0.03;
Field[1].FanPointsList = {5, 6};
Field[1].Quads = 1;
BoundaryLayer Field = 1;
Mesh 2;
Printf("%g", Mesh.NbQuadrangles);   // expect: 196
Printf("%g", Fabs(Mesh.NbTriangles - 1138) <= 0.15 * 1138);   // expect: 1
