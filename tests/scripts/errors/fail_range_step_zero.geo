l[] = {1:10:0};
// expect error: 1:13: invalid-range
