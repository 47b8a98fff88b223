// A mistake in a geometry statement's expressions is reported at the expression
// (and stops the run); the statements before it have built their entities.
lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lcc};
// expect error: 5:22: unknown-variable
