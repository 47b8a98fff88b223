// Min / Max of listed fields, the empty lists' 1e22 / -1e22, and the native
// FieldArgmin: which input of a Min controls the size.
Field[1] = MathEval;  Field[1].F = "x";
Field[2] = MathEval;  Field[2].F = "1 - x";
Field[3] = Min;       Field[3].FieldsList = {1, 2};
Field[4] = Max;       Field[4].FieldsList = {1, 2};
Printf("%g %g", FieldValue(3, 0.3, 0, 0), FieldArgmin(3, 0.3, 0, 0));   // expect: 0.3 1
Printf("%g %g", FieldValue(3, 0.8, 0, 0), FieldArgmin(3, 0.8, 0, 0));   // expect: 0.2 2
Printf("%g", FieldArgmin(3, 0.5, 0, 0));                                 // expect: 1
Printf("%g %g", FieldValue(4, 0.3, 0, 0), FieldValue(4, 0.8, 0, 0));    // expect: 0.7 0.8
Field[5] = Min;
Field[6] = Max;
Printf("%g %g %g", FieldValue(5, 0, 0, 0), FieldValue(6, 0, 0, 0), FieldArgmin(5, 0, 0, 0));   // expect: 1e+22 -1e+22 -1
// Options changed after a FieldValue call take effect (the cache is dropped).
Field[3].FieldsList = {2};
Printf("%g", FieldValue(3, 0.3, 0, 0));   // expect: 0.7
l[] = {1, 2};
Field[3].FieldsList = l[];
Printf("%g", FieldValue(3, 0.3, 0, 0));   // expect: 0.3
Printf("%g", newf);                       // expect: 7
Delete Field[6];
Printf("%g", newf);                       // expect: 6
Field[newf] = Min;
Printf("%g", newf);                       // expect: 7
