// A (co)homology request takes a domain and at most one subdomain, as in Gmsh 4.8.4's
// grammar (Parser/Gmsh.y: three lists are a syntax error there too).
Cohomology {{1}, {2}, {3}};
// expect error: 3:27: expected-token
