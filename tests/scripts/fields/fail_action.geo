// No kind has callbacks: `Field[n].Action;` is an unknown action.
Field[1] = Box;
Field[1].Update;
// expect error: 3:10: unknown-field-action
