// A boundary layer along the bottom of a 1 x 0.5 rectangle (Gmsh 4.8.4's 2D boundary
// layers): first layer 0.01, ratio 1.3, below thickness 0.05: 3 layers (0.01, 0.023,
// 0.0399; the next, 0.0619, is beyond). The bottom's 10 edges carry 3 quadrangles each,
// the sides leaving the layer's end points get the same heights as their first nodes.
// `gmsh -2` of this script: 30 quadrangles, 128 triangles, 113 nodes; ours must match
// the quadrangles and come within 15% of the rest.
// compare_with_gmsh: skip
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 0.5, 0, 0.1}; Point(4) = {0, 0.5, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Field[1] = BoundaryLayer;
Field[1].EdgesList = {1};     // Gmsh's deprecated name of CurvesList
Field[1].NodesList = {1, 2};  // and of PointsList
Field[1].hwall_n = 0.01;      // and of Size
Field[1].ratio = 1.3;
Field[1].thickness = 0.05;
Field[1].SizeFar = 0.1;
Field[1].Quads = 1;
BoundaryLayer Field = 1;
Mesh 2;
Printf("%g", Mesh.NbQuadrangles);   // expect: 30
Printf("%g", Fabs(Mesh.NbTriangles - 128) <= 0.15 * 128);   // expect: 1
Printf("%g", Fabs(Mesh.NbNodes - 113) <= 0.15 * 113);   // expect: 1
// As a size field, Gmsh's scalar value: min(SizeFar, d (Ratio - 1) + Size) within
// Thickness * Ratio = 0.065 of the curve and points, 1e22 beyond.
Printf("%g", Fabs(FieldValue(1, 0.5, 0.02, 0) - (0.02 * 0.3 + 0.01)) < 1e-6);   // expect: 1
Printf("%g", FieldValue(1, 0.5, 0.3, 0));   // expect: 1e+22
