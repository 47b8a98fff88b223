// examples/world_ocean.geo (Figures 9-10) at a smaller setting: GSHHG low resolution
// coarsened to 200 km and the 1-degree ETOPO5 grid. Checks the model and the size field
// at known places (the example's own Asserts), and prints the figures.
// compare_with_gmsh: skip (native Coastline and Field statements)
CoastAccuracy = 200e3;
CoastResolution = "l";   // GSHHG low from the system
CoastMinArea = 0;
BathyName = "etopo5_global_1deg.nc";
Quiet = 1;
EstimateStep = 0;   // the 1-degree triangle estimate takes 20 s of CPU
Include "../../../examples/world_ocean.geo";
Printf("%g sea, %g islands, %g control points", seas, islands, points);
Printf("mid-Pacific %.0f km by the wavelength: %g", pacific / Km, pacific_by == WaveField);
Printf("coast %.0f km", coast / Km);
Printf("North Pacific: %g water points, shore %.0f%%, wavelength %.0f%%, Hessian %.0f%%", np_total,
       100 * by_shore / np_total, 100 * by_wave / np_total, 100 * by_hessian / np_total);
// Water narrower than the 200 km accuracy that ends is filled (CloseNarrowWater; passages
// stay open). With the curve within gamma / 2 of the data (the default DeviationFactor
// 0.5) there are more control points (1150; 1011 as coarsening leaves them) and more
// straits narrower than gamma close between tighter curves (12 islands; 18).
// expect: 1 sea, 12 islands, 1150 control points
// expect: mid-Pacific 45 km by the wavelength: 1
// expect: coast 30 km
// expect: North Pacific: 851 water points, shore 7%, wavelength 92%, Hessian 1%
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 5,584 when written (every model point counts; -1 -o writes the 4,489 nodes of the
// physical groups).
Mesh 1;
Printf("1D mesh within 15%% of 5,584 nodes: %g", Fabs(Mesh.NbNodes - 5584) < 0.15 * 5584);
// expect: 1D mesh within 15% of 5,584 nodes: 1

// 2D (default front2d): 344,014 triangles, 97.1% with rho > 0.9 and 99.3% of
// edges within [0.7, 1.4] of the size when written; the test allows 10% on the count
// and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 344014: %g, rho > 0.9 share >= 0.941: %g, edges in range >= 0.963: %g",
       Fabs(Mesh.NbTriangles - 344014) < 0.1 * 344014, Mesh.StatsRhoAbove09 >= 0.941,
       Mesh.StatsEdgeInRange >= 0.963);
// expect: 2D: triangles within 10% of 344014: 1, rho > 0.9 share >= 0.941: 1, edges in range >= 0.963: 1
