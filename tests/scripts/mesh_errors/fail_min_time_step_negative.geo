// Mesh.MinTimeStep is a time step in seconds, 0 for off: a negative one is refused at the assignment.
Mesh.MinTimeStep = -5;   // expect error: 2:20: invalid-option-value
// compare_with_gmsh: skip
