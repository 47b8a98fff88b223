// Plugin(GSHHS).Run on a file that does not exist: the kernel's message at Run, and no
// output file is left behind.
Plugin(GSHHS).InFileName = "no_such_gshhs.b";
Plugin(GSHHS).OutFileName = "never_written.geo";
Plugin(GSHHS).Run;
// expect error: 5:1: plugin-error
