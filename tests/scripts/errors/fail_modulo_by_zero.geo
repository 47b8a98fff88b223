a = 7 % 0;
// expect error: 1:9: division-by-zero
