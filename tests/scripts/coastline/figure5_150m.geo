// Figure 5 of the paper at gamma = 150m: runs examples/gb_ireland_coarsening.geo (which
// asserts our GSHHG 2.3.7 counts within 5 %) and checks the paper's numbers with the
// tolerances of docs/coastlines.md section 8.
// compare_with_gmsh: skip (native Coastline statements)
gamma = 150;
quiet = 1;
Include "../../../examples/gb_ireland_coarsening.geo";
// Paper: 2,176 islands and 83,277 control points (GSHHS of 2008; GSHHG 2.3.7 holds more
// small islands and rocks: docs/coastlines.md section 8).
Printf("islands between 2176 and 2600: %g", islands >= 2176 && islands <= 2600);
Printf("control points within 5 %% of the paper's 83277: %g", Fabs(points - 83277) <= 0.05 * 83277);
// expect: islands between 2176 and 2600: 1
// expect: control points within 5 % of the paper's 83277: 1
