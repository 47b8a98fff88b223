n = 3;
Assert(n == 4, "n should be 4 but is %g", n);
// expect error: 2:8: assertion-failed
