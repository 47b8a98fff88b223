// The tutorial's model (docs/tutorial.md, examples/irish_sea.geo) runs as the tutorial
// shows it and prints what the tutorial says it prints.
// compare_with_gmsh: skip (native Coastline and Field statements)
Include "../../../examples/irish_sea.geo";
// expect: 2 sea(s), 6 islands, 7 open-boundary curves; mid-channel size 7.6 km
