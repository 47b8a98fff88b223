l[] = {1, 2, 3};
j = 3;
Printf("%g", l[j]);
// expect error: 3:16: index-out-of-range
