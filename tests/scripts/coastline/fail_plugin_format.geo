// Format is "gshhs" or "loops2" (Gmsh 2.6's choices).
Plugin(GSHHS).InFileName = "../../../data/gshhs/gshhs_c.b";
Plugin(GSHHS).OutFileName = "never_written.geo";
Plugin(GSHHS).Format = "shapefile";
Plugin(GSHHS).Run;
// expect error: 5:1: plugin-error
