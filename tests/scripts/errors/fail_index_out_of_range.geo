l[] = {1, 2, 3};
Printf("%g", l[3]);
// expect error: 2:16: index-out-of-range
