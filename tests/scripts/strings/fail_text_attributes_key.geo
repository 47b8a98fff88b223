// Gmsh ignores an unknown key; a misspelt one is an error here.
t = TextAttributes("Fontsize", "12");
// expect error: 2:20: builtin-error
