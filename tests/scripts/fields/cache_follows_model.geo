// A built field is reused between FieldValue calls only while the model is unchanged:
// moving, deleting, re-creating or splitting entities makes the next call see them.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Field[1] = Distance;
Field[1].PointsList = {1};
Printf("%g", FieldValue(1, 3, 4, 0));    // expect: 5
Translate {3, 0, 0} { Point{1}; }
Printf("%g", FieldValue(1, 3, 4, 0));    // expect: 4
Delete { Point{1}; }
Point(1) = {0, 4, 0};
Printf("%g", FieldValue(1, 3, 4, 0));    // expect: 3
Dilate {{0, 0, 0}, 0.5} { Point{1}; }
Printf("%g", FieldValue(1, 3, 2, 0));    // expect: 3
Field[2] = Distance;
Field[2].CurvesList = {1};
Line(1) = {1, 2};
// 20 samples per curve, the ends excluded as in Gmsh 4.8.4: the nearest is 1/19 of the way.
Printf("%.6f", FieldValue(2, 0, 2, 0));    // expect: 0.117688
Rotate {{0, 0, 1}, {1, 0, 0}, Pi} { Point{1}; }
Printf("%.6f", FieldValue(2, 2, -2, 0));   // expect: 0.117688
Printf("%.6f", FieldValue(2, 0, 2, 0));    // expect: 2.353756
