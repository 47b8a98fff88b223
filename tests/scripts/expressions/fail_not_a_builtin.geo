// Norm, Hypot3, Sign, Total and StrSplit are no Gmsh 4.8.4 functions: `Sign(2)`
// indexes a variable 'Sign', as in gmsh -0 ("Unknown variable").
x = Sign(2);
// expect error: 3:5: unknown-variable
