// The tutorial's model (docs/tutorial.md, examples/irish_sea.geo) meshed: what the tutorial
// prints before meshing (tests/tutorial/run_tutorial.py runs the page itself), the 1D and 2D
// counts and the time step it reports.
// compare_with_gmsh: skip (native Coastline and Field statements)
Include "../../../examples/irish_sea.geo";
// expect: 1 sea, 116 coast curves, 4 open-boundary curves
// expect: mid-channel: 7.6 km, set by the shore
// expect: Liverpool Bay: 4.2 km, set by the tide
// The model meshes in 1D (the coasts at the size field, no crossing curves): Mesh.NbNodes
// was 2356 when written and is 2754 with the coast within gamma / 2 of the data (every
// model point counts, the control points the bound put back and the dams included).
Mesh 1;
Printf("1D mesh within 15%% of 2754 nodes: %g", Fabs(Mesh.NbNodes - 2754) < 0.15 * 2754);
// expect: 1D mesh within 15% of 2754 nodes: 1

// 2D (default front2d, channels two elements across, quality floor 0.3): 12,729 triangles,
// 98.7% with rho > 0.9, 98.6% of edges within [0.7, 1.4] of the size when written, and a
// Courant time step of 15.7 s (a 111.5 m edge in 5.15 m of water at 3.23W 54.09N) since the
// Cymyran Strait (30.6 m, Anglesey) is closed by MinChannelWidth as it should be (it was
// 4.37 s, set by a 31 m edge there); the test allows 10% on the count, 3 points on the
// shares and 20% on the step.
Mesh 2;
Printf("2D: triangles within 10%% of 12729: %g, rho > 0.9 share >= 0.957: %g, edges in range >= 0.955: %g",
       Fabs(Mesh.NbTriangles - 12729) < 0.1 * 12729, Mesh.StatsRhoAbove09 >= 0.957,
       Mesh.StatsEdgeInRange >= 0.955);
// expect: 2D: triangles within 10% of 12729: 1, rho > 0.9 share >= 0.957: 1, edges in range >= 0.955: 1
Printf("time step within 20%% of 15.7 s: %g", Fabs(Mesh.StatsTimeStep - 15.7) < 0.2 * 15.7);
// expect: time step within 20% of 15.7 s: 1
