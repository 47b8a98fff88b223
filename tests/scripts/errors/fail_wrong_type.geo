s = "text";
x = s + 1;
// expect error: 2:5: wrong-type
