// An unknown kind: located at the name, with the closest kind.
Field[1] = Treshold;
// expect error: 2:12: unknown-field-kind
