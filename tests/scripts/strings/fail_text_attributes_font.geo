// Gmsh prints an error and falls back to Helvetica; here it is a script error
// at the font name.
t = TextAttributes("FontSize", "12", "Font", "Helvetic");
// expect error: 3:46: builtin-error
