// quality_floor_corner.geo's 5-degree corner on a PolarSphere's chart: the corner's place
// is given in degrees (at the chart's centre, the pole).
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
a = 5 * Pi / 180;
Point(3) = {0, 0, 0, 0.01}; Point(4) = {0.1, 0, 0, 0.01}; Point(5) = {0.1 * Cos(a), 0.1 * Sin(a), 0, 0.01};
Line(1) = {3, 4}; Line(2) = {4, 5}; Line(3) = {5, 3};
Curve Loop(1) = {1:3}; Plane Surface(1) = {1};
Mesh 2;   // expect warning: 10:1: mesh-quality-floor: surface 1: 2 triangles below Mesh.QualityFloor = 0.3 where the boundary makes an angle too sharp for it (under 9.4 degrees): 5.0 degrees at lon 0.0000, lat 90.0000
Printf("%d", Mesh.StatsRhoMin < 0.3);   // expect: 1
// compare_with_gmsh: skip
