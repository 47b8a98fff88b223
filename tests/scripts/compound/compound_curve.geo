// `Compound Curve{...};`: three lines meshed as one curve, 4.5 long at size 1: Gmsh's
// count for the whole, floor(4.5 + 1.99) = 6 nodes (each line alone would take 3 nodes,
// 7 in all). The inner end points keep a node: the node nearest each moves onto it.
// compare_with_gmsh: skip (Gmsh 4.8.4 also keeps a finer mesh of each original line,
// at Mesh.CompoundMeshSizeFactor, and writes the compound as a curve of its own: its
// node count is not ours; its compound curve has the same 5 edges)
Point(1) = {0, 0, 0, 1};
Point(2) = {1.5, 0, 0, 1};
Point(3) = {3, 0, 0, 1};
Point(4) = {4.5, 0, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Compound Curve{1, 2, 3};
Mesh 1;
Printf("%g", Mesh.NbNodes);   // expect: 6
// Not a chain: meshed one by one (Gmsh meshes them as one all the same).
Point(5) = {0, 1, 0, 1};
Point(6) = {1.5, 1, 0, 1};
Line(4) = {5, 6};
Compound Curve{4, 1};   // expect warning: 21:1: gmsh-compat
Compound Curve{4, 9};   // expect warning: 22:1: gmsh-compat
