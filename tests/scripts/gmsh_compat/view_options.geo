// Options of post-processing views (View.*, View[n].*) and of their drawing
// (PostProcessing.*) change only what Gmsh's window shows: each is evaluated, skipped and
// noted once per run (display-only), and the script runs on (tutorial/t4.geo stopped on
// them before). Output: gmsh 4.8.4 -0.
View "comments" { T2(10, -10, 0){ "Created with Gmsh" }; };
View[0].DoubleClickedCommand = "Printf('View[0] has been double-clicked!');";
View.Light = 0;
View[0].ColormapNumber = 2 + 1;
PostProcessing.HorizontalScales = 0;
Printf("after the view options");
// expect: after the view options
