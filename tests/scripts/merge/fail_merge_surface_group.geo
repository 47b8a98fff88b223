// A merged file's physical group of a discrete surface is not supported yet (the
// geometry model, which holds the groups, has no discrete surfaces): an error at the name.
Merge "square41_groups.msh";   // expect error: 3:7: not-supported-yet
