// Deleting a field that does not exist (Gmsh: "Cannot delete field id 7").
Field[1] = Box;
Delete Field[1];
Delete Field[7];
// expect error: 4:14: missing-field
