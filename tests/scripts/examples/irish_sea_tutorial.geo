// The tutorial's model (docs/tutorial.md, examples/irish_sea.geo) runs as the tutorial
// shows it and prints what the tutorial says it prints.
// compare_with_gmsh: skip (native Coastline and Field statements)
Include "../../../examples/irish_sea.geo";
// expect: 2 sea(s), 6 islands, 7 open-boundary curves; mid-channel size 7.6 km
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 2942 when written (every model point counts, control points included).
Mesh 1;
Printf("1D mesh within 15%% of 2942 nodes: %g", Fabs(Mesh.NbNodes - 2942) < 0.15 * 2942);
// expect: 1D mesh within 15% of 2942 nodes: 1

// 2D (default front2d): 12,648 triangles, 92.6% with rho > 0.9 and 98.1% of
// edges within [0.7, 1.4] of the size when written; the test allows 10% on the count
// and 3 points on the shares.
Mesh 2;
Printf("2D: triangles within 10%% of 12648: %g, rho > 0.9 share >= 0.896: %g, edges in range >= 0.951: %g",
       Fabs(Mesh.NbTriangles - 12648) < 0.1 * 12648, Mesh.StatsRhoAbove09 >= 0.896,
       Mesh.StatsEdgeInRange >= 0.951);
// expect: 2D: triangles within 10% of 12648: 1, rho > 0.9 share >= 0.896: 1, edges in range >= 0.951: 1
