Include "cycle_a.inc";
// expect error: 1:9: include-cycle
