// FieldValue takes (n, x, y, z) or (n, x, y, z, dim, tag).
Field[1] = Box;
h = FieldValue(1, 0, 0);
// expect error: 3:5: wrong-argument-count
