// A (co)homology request is skipped, but its lists are evaluated first: an undefined
// name in them is the script's mistake (gmsh 4.8.4 -0: "Unknown variable 'dom'").
Homology {{dom}, {2}};
// expect error: 3:12: unknown-variable
