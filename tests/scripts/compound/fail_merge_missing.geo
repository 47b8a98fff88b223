// Merging a file that does not exist is an error at its name (Gmsh stops there too).
Point(1) = {0, 0, 0};
Merge "no_such_mesh.msh";
// expect error: 3:7: cannot-open-file
