// A field id in a list must fit an int.
Field[1] = Min;
Field[1].FieldsList = {1, 1e12};
// expect error: 3:23: bad-field-value: option 'FieldsList' of Field[1]: 1000000000000 is not a valid id
