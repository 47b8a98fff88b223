// Plugin(GSHHS) options keep Gmsh 2.6's names: a misspelt one is refused with a suggestion.
Plugin(GSHHS).InFile = "gshhs_c.b";
// expect error: 2:15: unknown-plugin-option
