// The layer of boundary_layer_quads.geo with Quads = 0 (the default): each of its 30
// quadrangles split into two triangles. `gmsh -2`: 188 triangles, no quadrangle.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].CurvesList = {1};
Field[1].PointsList = {1, 2};
Field[1].Size = 0.01;
Field[1].Ratio = 1.3;
Field[1].Thickness = 0.05;
Field[1].SizeFar = 0.1;
BoundaryLayer Field = 1;
Mesh 2;
Printf("%g", Mesh.NbQuadrangles);   // expect: 0
Printf("%g", Fabs(Mesh.NbTriangles - 188) <= 0.15 * 188);   // expect: 1
