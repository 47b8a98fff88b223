// Threshold (linear, sigmoid, StopAtDistMax) on a MathEval input F = x, with
// the deprecated aliases IField, LcMin and LcMax sharing the new names' storage.
Field[1] = MathEval;
Field[1].F = "x";
Field[2] = Threshold;
Field[2].IField = 1;
Field[2].LcMin = 0.1;
Field[2].LcMax = 1;
Field[2].DistMin = 1;
Field[2].DistMax = 3;
Printf("%g", FieldValue(2, 0, 0, 0));     // expect: 0.1
Printf("%g", FieldValue(2, 1, 0, 0));     // expect: 0.1
Printf("%g", FieldValue(2, 2, 0, 0));     // expect: 0.55
Printf("%g", FieldValue(2, 2.5, 0, 0));   // expect: 0.775
Printf("%g", FieldValue(2, 5, 0, 0));     // expect: 1
// The new names read and overwrite the same slots.
Field[2].SizeMax = 2;
Printf("%g", FieldValue(2, 2, 0, 0));     // expect: 1.05
Field[2].SizeMax = 1;
// Sigmoid: s = e^(12r-6)/(1+e^(12r-6)) with r = (d-DistMin)/(DistMax-DistMin).
Field[2].Sigmoid = 1;
Printf("%g", FieldValue(2, 2, 0, 0));     // expect: 0.55
Printf("%g", FieldValue(2, 1.5, 0, 0));   // expect: 0.142683
Field[2].Sigmoid = 0;
// StopAtDistMax: no constraint (1e22) from DistMax on.
Field[2].StopAtDistMax = 1;
Printf("%g", FieldValue(2, 2, 0, 0));     // expect: 0.55
Printf("%g", FieldValue(2, 3, 0, 0));     // expect: 1e+22
Printf("%g", FieldValue(2, 7, 0, 0));     // expect: 1e+22
