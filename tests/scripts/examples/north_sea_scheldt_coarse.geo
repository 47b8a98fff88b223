// examples/north_sea_scheldt.geo (Figure 13) at a smaller setting: 2 km in the estuary and
// 20 km on the coasts. The example asserts the sizes at Antwerp, at the mouth, 80 km off it
// and in the central North Sea; this prints the model's figures. The domain is the
// north-west European shelf polygon (stdlib/regions.geo), open in one piece along the
// shelf break.
// compare_with_gmsh: skip (native Coastline and Field statements)
EstuarySize = 2000;
CoastSize = 20e3;
Quiet = 1;
Include "../../../examples/north_sea_scheldt.geo";
Printf("%g seas, %g open-boundary curves, %g kept shore points", seas, #open[], #ShorePoints[]);
Printf("Antwerp %.0f m, central North Sea %.0f km", antwerp, offshore / Km);
// The OpenStreetMap patch carries the estuary up to Antwerp (GSHHG alone stops 17 km short).
Printf("Antwerp within 3 km of the shore: %g", antwerp_shore < 3e3);
// expect: 1 seas, 1 open-boundary curves, 782 kept shore points
// expect: Antwerp 2000 m, central North Sea 50 km
// expect: Antwerp within 3 km of the shore: 1
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 2,045 when written (every model point counts, control points included; with
// Mesh.ElementsAcrossChannels = 2, the default, every channel gets two 1D edges across);
// 2,361 with the coast within gamma / 2 of the data (the control points put back count).
Mesh 1;
Printf("1D mesh within 15%% of 2361 nodes: %g", Fabs(Mesh.NbNodes - 2361) < 0.15 * 2361);
// expect: 1D mesh within 15% of 2361 nodes: 1

// 2D (default front2d): 6,424 triangles, 92.7% with rho > 0.9 and 95.4% of edges within
// [0.7, 1.4]; the test allows 10% on the count and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 6424: %g, rho > 0.9 share >= 0.897: %g, edges in range >= 0.924: %g",
       Fabs(Mesh.NbTriangles - 6424) < 0.1 * 6424, Mesh.StatsRhoAbove09 >= 0.897,
       Mesh.StatsEdgeInRange >= 0.924);
// expect: 2D: triangles within 10% of 6424: 1, rho > 0.9 share >= 0.897: 1, edges in range >= 0.924: 1
// Mesh.QualityFloor (0.3 by default): no triangle below it on this real coast.
Printf("rho min >= 0.3: %g", Mesh.StatsRhoMin >= 0.3);
// expect: rho min >= 0.3: 1
