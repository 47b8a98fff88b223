// examples/great_barrier_reef.geo (Figure 14) at a smaller setting: 1 km at Lizard Island
// and 20 km on the other coasts. The example asserts that Lizard Island stays in the model
// (its gamma is the Lizard criterion), the size there, and that the bathymetry decides in
// the deep Coral Sea.
// compare_with_gmsh: skip (native Coastline and Field statements)
LizardSize = 1000;
CoastSize = 20e3;
Quiet = 1;
EstimateStep = 0.5;
EstimateFineStep = 0.05;
Include "../../../examples/great_barrier_reef.geo";
Printf("%g sea, %g islands, %g open-boundary curves", seas, islands, #open[]);
Printf("Lizard Island: coast %.1f km from its centre, size %.0f m", lizard_shore / Km, lizard);
Printf("Coral Sea %.1f km by the wavelength: %g", coral_sea / Km, coral_sea_by == WaveField);
Printf("estimate: %.0f triangles, %.0f%% near Lizard Island", all_triangles, 100 * EstimatedTriangles / all_triangles);
// expect: 1 sea, 4 islands, 6 open-boundary curves
// expect: Lizard Island: coast 0.7 km from its centre, size 1000 m
// expect: Coral Sea 28.6 km by the wavelength: 1
// expect: estimate: 3511 triangles, 26% near Lizard Island
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 586 when written (every model point counts, control points included).
Mesh 1;
// 682 with Mesh.ElementsAcrossChannels = 2 (the default; 586 without): every channel gets
// two 1D edges across, so narrow straits and inlets add coast nodes.
Printf("1D mesh within 15%% of 682 nodes: %g", Fabs(Mesh.NbNodes - 682) < 0.15 * 682);
// expect: 1D mesh within 15% of 682 nodes: 1

// 2D (default front2d): 4,558 triangles, 88.3% with rho > 0.9 and 96.1% of
// edges within [0.7, 1.4] of the size when written; the test allows 10% on the count
// and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 4558: %g, rho > 0.9 share >= 0.853: %g, edges in range >= 0.931: %g",
       Fabs(Mesh.NbTriangles - 4558) < 0.1 * 4558, Mesh.StatsRhoAbove09 >= 0.853,
       Mesh.StatsEdgeInRange >= 0.931);
// expect: 2D: triangles within 10% of 4558: 1, rho > 0.9 share >= 0.853: 1, edges in range >= 0.931: 1
// Mesh.QualityFloor (0.3 by default): no triangle below it on this real coast.
Printf("rho min >= 0.3: %g", Mesh.StatsRhoMin >= 0.3);
// expect: rho min >= 0.3: 1
