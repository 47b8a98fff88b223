// 1D mesh of the 743 GSHHG crude coastlines of world_c.txt (closed BSplines on a unit
// PolarSphere, tests/data/geo_scripts/world_c.geo) with a size field finer near the
// equator; node count against gmsh 4.8.4 -1. The surface is deleted: as its boundary the
// crude coastlines cannot be meshed (fail_world_c_intersection.geo), as free curves they can.
Include "../../data/geo_scripts/world_c.geo";
Delete { Surface{1}; }
Field[1] = MathEval;
Field[1].F = "0.004 + 0.02 * Fabs(z)";
Background Field = 1;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh 1;
gmsh_nodes = 12214;   // Mesh.NbNodes printed by gmsh 4.8.4 here (its -1 run reports 12208 nodes, as we have)
Printf("within 5 percent: %g", Fabs(Mesh.NbNodes - gmsh_nodes) <= 0.05 * gmsh_nodes);   // expect: within 5 percent: 1
