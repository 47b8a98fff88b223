// Merge of an STL triangulation (Gmsh's tutorial t13 remeshes one in 3D: ClassifySurfaces,
// CreateGeometry, a volume) stops at the file's name with an error that says what is not
// supported, rather than running on to errors about what the surface would have made.
Merge "flat.stl";   // expect error: 4:7: not-supported-yet: cannot merge STL file 'flat.stl': Gmsh makes its triangles a discrete surface to split along sharp edges (ClassifySurfaces), reparametrise (CreateGeometry) and remesh in 3D; remeshing an STL surface is not supported (stereomesh meshes planar and spherical 2D models)
ClassifySurfaces{Pi / 4, 1, 0};
CreateGeometry;
