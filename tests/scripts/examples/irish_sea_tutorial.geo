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
