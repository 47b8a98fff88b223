// Box, Ball, Cylinder and Constant at known points against their formulas
// (docs/fields.md), evaluated through the native FieldValue(n, x, y, z).
Field[1] = Box;
Field[1].VIn = 0.1;  Field[1].VOut = 1;
Field[1].XMin = 0;   Field[1].XMax = 1;
Field[1].YMin = 0;   Field[1].YMax = 2;
Field[1].ZMin = -1;  Field[1].ZMax = 1;
Printf("%g", FieldValue(1, 0.5, 1, 0));   // expect: 0.1
Printf("%g", FieldValue(1, 1, 2, 1));     // expect: 0.1
Printf("%g", FieldValue(1, 1.5, 1, 0));   // expect: 1
// With a Thickness, VIn + (d/Thickness)(VOut - VIn) at distance d from the box.
Field[1].Thickness = 2;
Printf("%g", FieldValue(1, 1.5, 1, 0));   // expect: 0.325
Printf("%g", FieldValue(1, 4, 1, 0));     // expect: 1

Field[2] = Ball;
Field[2].XCenter = 1;  Field[2].YCenter = 2;  Field[2].ZCenter = 3;
Field[2].Radius = 1;   Field[2].VIn = 0.2;    Field[2].VOut = 2;
Printf("%g", FieldValue(2, 1, 2, 3.5));   // expect: 0.2
Printf("%g", FieldValue(2, 1, 2, 4.5));   // expect: 2
Field[2].Thickness = 1;
Printf("%g", FieldValue(2, 1, 2, 4.5));   // expect: 1.1
Printf("%g", FieldValue(2, 1, 5, 3));     // expect: 2

Field[3] = Cylinder;
Field[3].ZAxis = 2;  Field[3].Radius = 1;  Field[3].VIn = 3;  Field[3].VOut = 7;
Printf("%g", FieldValue(3, 0.5, 0, 1.9));  // expect: 3
Printf("%g", FieldValue(3, 0.5, 0, 2.1));  // expect: 7
Printf("%g", FieldValue(3, 1.1, 0, 0));    // expect: 7

// Constant (Gmsh >= 4.9): VIn on the listed entities, VOut elsewhere and
// without an entity; FieldValue's optional (dim, tag) names the entity.
Field[4] = Constant;
Field[4].VIn = 0.5;  Field[4].VOut = 4;  Field[4].SurfacesList = {6};
Printf("%g", FieldValue(4, 0, 0, 0));        // expect: 4
Printf("%g", FieldValue(4, 0, 0, 0, 2, 6));  // expect: 0.5
Printf("%g", FieldValue(4, 0, 0, 0, 2, 7));  // expect: 4
Printf("%g", FieldValue(4, 0, 0, 0, 1, 6));  // expect: 4
