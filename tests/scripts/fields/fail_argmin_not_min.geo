// FieldArgmin needs a Min field.
Field[1] = Box;
h = FieldArgmin(1, 0, 0, 0);
// expect error: 3:17: builtin-error
