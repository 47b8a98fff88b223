// examples/north_sea_scheldt.geo (Figure 13) at a smaller setting: 2 km in the estuary and
// 20 km on the coasts. The example asserts the sizes at Antwerp, at the mouth, 80 km off it
// and in the central North Sea; this prints the model's figures.
// compare_with_gmsh: skip (native Coastline and Field statements)
EstuarySize = 2000;
CoastSize = 20e3;
Quiet = 1;
Include "../../../examples/north_sea_scheldt.geo";
Printf("%g seas, %g open-boundary curves, %g kept shore points", seas, #open[], #ShorePoints[]);
Printf("Antwerp %.0f m, central North Sea %.0f km", antwerp, offshore / Km);
// expect: 3 seas, 15 open-boundary curves, 366 kept shore points
// expect: Antwerp 2000 m, central North Sea 50 km
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 836 when written (every model point counts, control points included).
Mesh 1;
Printf("1D mesh within 15%% of 836 nodes: %g", Fabs(Mesh.NbNodes - 836) < 0.15 * 836);
// expect: 1D mesh within 15% of 836 nodes: 1

// 2D (default front2d): 2,307 triangles, 89.5% with rho > 0.9 and 97.0% of
// edges within [0.7, 1.4] of the size when written; the test allows 10% on the count
// and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 2307: %g, rho > 0.9 share >= 0.865: %g, edges in range >= 0.940: %g",
       Fabs(Mesh.NbTriangles - 2307) < 0.1 * 2307, Mesh.StatsRhoAbove09 >= 0.865,
       Mesh.StatsEdgeInRange >= 0.940);
// expect: 2D: triangles within 10% of 2307: 1, rho > 0.9 share >= 0.865: 1, edges in range >= 0.940: 1
