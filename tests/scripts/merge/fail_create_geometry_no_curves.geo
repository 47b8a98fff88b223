// CreateGeometry of a discrete surface whose file has no curves along its boundary
// (triangles_only22.msh: square22.msh's five triangles alone): Gmsh's CreateTopology would
// make the curves, stereomesh does not yet; an error at the statement.
Merge "triangles_only22.msh";
CreateTopology;
CreateGeometry;   // expect error: 6:1: not-supported-yet: CreateGeometry of discrete surface 31: its boundary edge between nodes 1 and 4 lies on no discrete curve; stereomesh needs the merged file's curves along the whole boundary (it does not make them, as Gmsh's CreateTopology does, yet)
