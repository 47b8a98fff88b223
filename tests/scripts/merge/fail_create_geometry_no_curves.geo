// CreateGeometry of a discrete surface whose file has no curves along its boundary
// (triangles_only22.msh: square22.msh's five triangles alone): Gmsh's CreateTopology would
// make the curves, stereomesh does not yet; an error at the statement.
Merge "triangles_only22.msh";
CreateTopology;
CreateGeometry;   // expect error: 6:1: not-supported-yet
