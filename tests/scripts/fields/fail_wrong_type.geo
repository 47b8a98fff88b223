// A string given to a number option.
Field[1] = Box;
Field[1].VIn = "small";
// expect error: 3:16: wrong-field-option-type: Field[1]: option 'VIn' of field kind 'Box' expects a number, got a string
