z = 3;
z[1] = 5;
// expect error: 2:1: not-a-list
