a = 4;
b = a / (a - 4);
// expect error: 2:10: division-by-zero
