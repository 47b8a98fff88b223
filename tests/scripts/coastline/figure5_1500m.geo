// Figure 5 of the paper at gamma = 1500m: runs examples/gb_ireland_coarsening.geo (which
// asserts our GSHHG 2.3.7 counts within 5 %) and checks the paper's numbers with the
// tolerances of docs/coastlines.md section 8.
// compare_with_gmsh: skip (native Coastline statements)
gamma = 1500;
quiet = 1;
Include "../../../examples/gb_ireland_coarsening.geo";
// Paper: 152 islands.
Printf("islands between 140 and 165: %g", islands >= 140 && islands <= 165);
Printf("control points between 9000 and 11500: %g", points >= 9000 && points <= 11500);
// expect: islands between 140 and 165: 1
// expect: control points between 9000 and 11500: 1
