// Duplicata and MeshSize of entities that do not exist: Gmsh reports an error for the
// Duplicata, ignores the MeshSize and goes on; we skip them with a warning.
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
p[] = Translate{0, 1, 0}{ Duplicata{ Point{1, 7, 2}; } };
Printf("%g %g %g", #p[], p[0], p[1]);  // expect: 2 3 4
MeshSize{2, 9} = 0.25;
Printf("%g", newp);  // expect: 5
// expect warning: 5:27: gmsh-compat: Duplicata of point 7, which does not exist: Gmsh reports an error and copies the other entities; we copy the others and warn
// expect warning: 7:1: gmsh-compat: MeshSize of point 9, which does not exist: Gmsh ignores it; so do we
