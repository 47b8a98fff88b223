// On a model on the sphere Mesh.QualityFloor's default (0.3) applies: the sliver of
// quality_floor_flat_default.geo drawn on a PolarSphere's chart gets its curve edges split.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
Point(3) = {0, 0, 0, 1};
Point(4) = {0.1, 0.1, 0, 1};
Point(5) = {0.1, 0.2, 0, 1};
Line(1) = {3, 4};
Line(2) = {4, 5};
Line(3) = {5, 3};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 2;
Printf("%g", Mesh.NbNodes > 3);   // expect: 1
Printf("%g", Mesh.StatsRhoMin >= 0.3);   // expect: 1
// compare_with_gmsh: skip
