// A field id in a list must be a whole number: 2.5 is a mistake, not field 2.
Field[1] = Min;
Field[1].FieldsList = {1, 2.5};
// expect error: 3:23: wrong-field-option-type: Field[1]: option 'FieldsList' of field kind 'Min' expects field ids, got 2.5
