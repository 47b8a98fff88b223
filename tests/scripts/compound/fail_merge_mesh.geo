// Merging a mesh (merge_square.msh, a unit square in two triangles, MSH 4.1 written by
// gmsh 4.8.4): Gmsh makes its elements discrete points, curves and surfaces, which
// stereomesh's model has no place for yet: reported where it is written, and skipped.
Merge "merge_square.msh";
Printf("%g", 1);   // expect: 1
// expect error: 4:1: not-supported-yet
