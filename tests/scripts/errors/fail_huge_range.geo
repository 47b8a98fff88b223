l[] = {0:1e10};
// expect error: 1:8: limit-exceeded
