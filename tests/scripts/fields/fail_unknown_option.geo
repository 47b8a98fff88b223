// An unknown option: located at the option name, with the closest option.
Field[1] = Threshold;
Field[1].DistMaxx = 3;
// expect error: 3:10: unknown-field-option
