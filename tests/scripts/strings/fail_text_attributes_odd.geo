// Attributes are key, value pairs.
t = TextAttributes("Font", "Courier", "Align");
// expect error: 2:5: builtin-error
