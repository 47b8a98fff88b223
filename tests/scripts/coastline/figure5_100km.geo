// Figure 5 of the paper at gamma = 100km: runs examples/gb_ireland_coarsening.geo (which
// asserts our GSHHG 2.3.7 counts within 5 %) and checks the paper's numbers with the
// tolerances of docs/coastlines.md section 8.
// compare_with_gmsh: skip (native Coastline statements)
gamma = 100000;
quiet = 1;
Include "../../../examples/gb_ireland_coarsening.geo";
// Paper: 2 contours, Great Britain and Ireland.
Printf("islands: %g", islands);
Printf("control points between 30 and 60: %g", points >= 30 && points <= 60);
// expect: islands: 2
// expect: control points between 30 and 60: 1
