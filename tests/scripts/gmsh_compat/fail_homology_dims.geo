// With dimensions, a (co)homology request takes the domain and the subdomain both, as in
// Gmsh 4.8.4's grammar (Parser/Gmsh.y: "Homology (1) {{1}};" is a syntax error there too).
Homology (1) {{1}};
// expect error: 3:19: expected-token
