// Only Gmsh's built-in kernel exists ("Gmsh" is its other name).
SetFactory("Built-in");
SetFactory("Gmsh");
SetFactory("OpenCASCADE");
// expect error: 4:1: not-supported-yet
