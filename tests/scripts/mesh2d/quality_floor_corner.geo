// A 5-degree corner: no triangle there can reach rho 0.3 (the isoceles limit is 9.45
// degrees); the floor reports it once, with the angle and place, and meshes on. The
// model is flat, where the floor is off unless set (quality_floor_flat_default.geo).
Printf("%g", Mesh.QualityFloor);   // expect: 0.3
Mesh.QualityFloor = 0.3;
a = 5 * Pi / 180;
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {Cos(a), Sin(a), 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1:3}; Plane Surface(1) = {1};
Mesh 2;   // expect warning: 10:1: mesh-quality-floor: surface 1: 2 triangles below Mesh.QualityFloor = 0.3 where the boundary makes an angle too sharp for it (under 9.4 degrees): 5.0 degrees at (0, 0, 0)
Printf("%d", Mesh.StatsRhoMin < 0.3);   // expect: 1
// compare_with_gmsh: skip
