// The World Ocean (GSHHG low resolution coarsened to 100 km, the 1-degree
// ETOPO5 grid) with a quality floor of 0.8, far above what the refinement reaches
// everywhere. The floor's undo of its flips (split_with_flips) used to leave twins that
// pointed at the wrong sides: this run ended in SIGSEGV (an invalid read past the cavity
// boundary in PointInserter::insert) after 3 s, higher floors on the full example never
// ended. Now it ends with a valid mesh and reports, with their places, what it could not
// raise (the work is bounded).
// compare_with_gmsh: skip (native Coastline and Field statements)
CoastAccuracy = 100e3;
CoastResolution = "l";   // GSHHG low from the system
CoastMinArea = 0;
BathyName = "etopo5_global_1deg.nc";
Quiet = 1;
EstimateStep = 0;
Include "../../../examples/world_ocean.geo";
Mesh.QualityFloor = 0.8;
Mesh 2;
Printf("meshed: %g, rho min > 0: %g, rho > 0.9 share >= 0.9: %g", Mesh.NbTriangles > 300000, Mesh.StatsRhoMin > 0,
       Mesh.StatsRhoAbove09 >= 0.9);
// expect: meshed: 1, rho min > 0: 1, rho > 0.9 share >= 0.9: 1
