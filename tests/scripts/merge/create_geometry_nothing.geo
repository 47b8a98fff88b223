// CreateGeometry with no discrete entity left without a geometry does nothing, in Gmsh as
// here; we say so with a located warning: first before any Merge, then a second time
// after the first gave the merged square its geometry.
Point(1) = {0, 0, 0, 1};
CreateGeometry;   // expect warning: 5:1: gmsh-compat: CreateGeometry has nothing to do: no discrete curve or surface is left without a geometry (none was merged, or a CreateGeometry before gave them one); Gmsh does nothing either
Merge "square22.msh";
CreateGeometry;
CreateGeometry;   // expect warning: 8:1: gmsh-compat: CreateGeometry has nothing to do: no discrete curve or surface is left without a geometry (none was merged, or a CreateGeometry before gave them one); Gmsh does nothing either
s[] = Surface{:};
Printf("surfaces: %g", #s[]);   // expect: surfaces: 1
