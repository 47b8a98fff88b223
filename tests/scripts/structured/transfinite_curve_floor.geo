// A transfinite curve keeps its node count beside an unstructured face: the quality floor
// (Mesh.QualityFloor 0.3, set: on a flat model it is off by default) splits curve edges
// to lift slivers, but never those of a
// `Transfinite Curve{c} = n`, which means n nodes in Gmsh whatever the face beside it
// becomes. The strip 1 x 0.01 is all slivers; the floor may add interior points, so the
// test counts the boundary nodes: a triangulated polygon with b boundary and i interior
// nodes has b + 2 i - 2 triangles (gmsh -2: 22 nodes, 20 triangles, so b = 22).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 0.01, 0, 0.1}; Point(4) = {0, 0.01, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 11;
Mesh.QualityFloor = 0.3;   // gmsh -0: an unknown option, reported, the script goes on
Mesh 2;   // expect warning: 14:1: mesh-quality-floor: surface 1: 20 triangles still below Mesh.QualityFloor = 0.3 after 1 round and 0 new points (the work is bounded); the worst, rho 0.1891, near (0.0333333, 0.00333333, 0)
Printf("%g boundary nodes", 2 * Mesh.NbNodes - Mesh.NbTriangles - 2);   // expect: 22 boundary nodes
