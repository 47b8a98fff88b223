// A value that is not a finite number (1e308 * 10 overflows to inf).
Field[1] = Box;
Field[1].VIn = 1e308 * 10;
// expect error: 3:16: bad-field-value: option 'VIn' of Field[1] is not finite
