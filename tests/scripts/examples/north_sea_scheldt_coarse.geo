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
// 1131 with Mesh.ElementsAcrossChannels = 2 (the default; 836 without): every channel gets
// two 1D edges across, so narrow straits and inlets add coast nodes.
Printf("1D mesh within 15%% of 1131 nodes: %g", Fabs(Mesh.NbNodes - 1131) < 0.15 * 1131);
// expect: 1D mesh within 15% of 1131 nodes: 1

// 2D (default front2d): 3,072 triangles, 85.4% with rho > 0.9 and 91.7% of edges within
// [0.7, 1.4] with Mesh.ElementsAcrossChannels = 2 (the default; 2,307, 89.5% and 97.0% without:
// the channels narrower than the size now get two elements across, which costs shares);
// the test allows 10% on the count and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 3072: %g, rho > 0.9 share >= 0.824: %g, edges in range >= 0.887: %g",
       Fabs(Mesh.NbTriangles - 3072) < 0.1 * 3072, Mesh.StatsRhoAbove09 >= 0.824,
       Mesh.StatsEdgeInRange >= 0.887);
// expect: 2D: triangles within 10% of 3072: 1, rho > 0.9 share >= 0.824: 1, edges in range >= 0.887: 1
// Mesh.QualityFloor (0.3 by default): no triangle below it on this real coast.
Printf("rho min >= 0.3: %g", Mesh.StatsRhoMin >= 0.3);
// expect: rho min >= 0.3: 1
