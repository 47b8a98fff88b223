// examples/arctic.geo (Figure 11) at a smaller setting: 60 km in the Canadian Arctic
// Archipelago, 120 km on the other coasts, and a 2-degree triangle-count estimate (0.5
// degree in the example at 20/40 km: 17,692 triangles; the paper's mesh: 17,053). The
// example asserts the sizes in Barrow Strait, off Norway and at the North Pole.
// compare_with_gmsh: skip (native Coastline and Field statements)
ArchipelagoSize = 60e3;
CoastSize = 120e3;
EstimateStep = 2;
Quiet = 1;
Include "../../../examples/arctic.geo";
Printf("%g sea, %g islands, %g open-boundary curves", seas, islands, #open[]);
Printf("archipelago points are a subset: %g", #caa_points[] > 0 && #caa_points[] < #all_points[]);
Printf("Barrow Strait %.0f km, North Pole %.0f km", sizes[0] / Km, sizes[2] / Km);
Printf("estimate: %.0f triangles", EstimatedTriangles);
// expect: 1 sea, 31 islands, 15 open-boundary curves
// expect: archipelago points are a subset: 1
// expect: Barrow Strait 68 km, North Pole 182 km
// expect: estimate: 3557 triangles
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 2056 when written (every model point counts, control points included).
Mesh 1;
Printf("1D mesh within 15%% of 2056 nodes: %g", Fabs(Mesh.NbNodes - 2056) < 0.15 * 2056);
// expect: 1D mesh within 15% of 2056 nodes: 1

// 2D (default front2d): 4,536 triangles, 88.8% with rho > 0.9 and 96.7% of
// edges within [0.7, 1.4] of the size when written; the test allows 10% on the count
// and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 4536: %g, rho > 0.9 share >= 0.858: %g, edges in range >= 0.937: %g",
       Fabs(Mesh.NbTriangles - 4536) < 0.1 * 4536, Mesh.StatsRhoAbove09 >= 0.858,
       Mesh.StatsEdgeInRange >= 0.937);
// expect: 2D: triangles within 10% of 4536: 1, rho > 0.9 share >= 0.858: 1, edges in range >= 0.937: 1
