// examples/arctic.geo at its own sizes (20 km in the archipelago, 40 km on the other coasts):
// the quality floor holds everywhere. Where the 50N parallel cuts Vancouver Island's coast
// (127.14W), the open boundary between the two cut points is 98 m long beside 7 km coast
// edges: the needle there (rho 0.026 before) needs the coast edge cut at the open side's
// length from the corner, and that cut point lies beyond the needle's far side (the coast
// bends into the water), so a flip comes first (src/mesh/quality_floor.cpp).
// compare_with_gmsh: skip (native Coastline and Field statements)
EstimateStep = 0;
Quiet = 1;
Include "../../../examples/arctic.geo";
Mesh 2;
Printf("rho min >= 0.3: %g", Mesh.StatsRhoMin >= 0.3);
// expect: rho min >= 0.3: 1
