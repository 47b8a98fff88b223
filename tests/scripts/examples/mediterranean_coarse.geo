// examples/mediterranean.geo (RegionalSea: Suez, Bosporus and Dardanelles closed, the
// central sea kept) meshed in 2D: one sea, its only open boundary the West side at
// Gibraltar, so that fort.14 has one open boundary. 11,352 nodes and 20,381 triangles when
// written; the test allows 10%.
// compare_with_gmsh: skip (native Coastline and Field statements)
Quiet = 1;
Include "../../../examples/mediterranean.geo";
Printf("%g sea(s), %g open curve(s), %g on the West side", #RegionalSurfaces[], #RegionalOpenCurves[],
       #Coastline{1, "OpenCurves", "West"});
// expect: 1 sea(s), 1 open curve(s), 1 on the West side
Mesh 2;
Printf("triangles within 10%% of 20381: %g", Fabs(Mesh.NbTriangles - 20381) < 0.1 * 20381);
// expect: triangles within 10% of 20381: 1
// Mesh.QualityFloor (0.3 by default): no triangle below it on this real coast.
Printf("rho min >= 0.3: %g", Mesh.StatsRhoMin >= 0.3);
// expect: rho min >= 0.3: 1
