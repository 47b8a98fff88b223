// Restrict: Field[InField] on the listed entities, 1e22 on the others, and
// InField itself without an entity (FieldValue's optional dim, tag).
Field[1] = MathEval;
Field[1].F = "7";
Field[2] = Restrict;
Field[2].IField = 1;
Field[2].FacesList = {6};
Field[2].EdgesList = {3};
Printf("%g", FieldValue(2, 0, 0, 0));         // expect: 7
Printf("%g", FieldValue(2, 0, 0, 0, 2, 6));   // expect: 7
Printf("%g", FieldValue(2, 0, 0, 0, 2, 5));   // expect: 1e+22
Printf("%g", FieldValue(2, 0, 0, 0, 1, 3));   // expect: 7
Printf("%g", FieldValue(2, 0, 0, 0, 0, 3));   // expect: 1e+22
// Composites pass the entity on to their inputs.
Field[3] = MathEval;
Field[3].F = "9";
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Printf("%g %g", FieldValue(4, 0, 0, 0, 2, 6), FieldArgmin(4, 0, 0, 0, 2, 6));   // expect: 7 2
Printf("%g %g", FieldValue(4, 0, 0, 0, 2, 5), FieldArgmin(4, 0, 0, 0, 2, 5));   // expect: 9 3
