// CreateGeometry of a discrete surface that is not flat (tilted22.msh: square22.msh with
// its middle node lifted by 0.25): Gmsh reparametrises it in 3D, which stereomesh does not
// do yet; an error at the statement that names the surface and the node.
Merge "tilted22.msh";
CreateGeometry;   // expect error: 5:1: not-supported-yet: CreateGeometry of discrete surface 31: its node 6 lies 0.208333 off the plane of its elements; stereomesh gives a geometry to flat discrete surfaces only (remeshing a curved surface in 3D, as Gmsh's reparametrisation does, is not supported yet)
