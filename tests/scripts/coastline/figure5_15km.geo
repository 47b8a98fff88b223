// Figure 5 of the paper at gamma = 15km: runs examples/gb_ireland_coarsening.geo (which
// asserts our GSHHG 2.3.7 counts within 5 %) and checks the paper's numbers with the
// tolerances of docs/coastlines.md section 8.
// compare_with_gmsh: skip (native Coastline statements)
gamma = 15000;
quiet = 1;
Include "../../../examples/gb_ireland_coarsening.geo";
// Paper: about 15 contours (the Isle of Wight appears).
Printf("islands between 13 and 18: %g", islands >= 13 && islands <= 18);
Printf("control points between 500 and 700: %g", points >= 500 && points <= 700);
// expect: islands between 13 and 18: 1
// expect: control points between 500 and 700: 1
