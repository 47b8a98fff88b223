// The kernel cannot run Point yet, but the statement's expressions are
// evaluated: a mistake in them is reported now (and stops the run).
lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lcc};
// expect error: 4:1: not-supported-yet
// expect error: 5:22: unknown-variable
