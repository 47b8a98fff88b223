// MathEval (MathEx syntax: unary minus binds tighter than ^, % is fmod, F<n>),
// Param (coordinate change) and LonLat (radians, RadiusStereo, FromStereo).
Field[1] = MathEval;
Field[1].F = "-x^2 + 7 % 4 + sqrt(abs(y))";
Printf("%g", FieldValue(1, 3, -16, 0));   // expect: 16
Field[2] = MathEval;
Field[2].F = "x + 10*y";
Field[3] = MathEval;
Field[3].F = Sprintf("F2 * %g + F1", 2);
Printf("%g", FieldValue(3, 3, 1, 0));     // expect: 39
Field[4] = Param;
Field[4].InField = 2;
Field[4].FX = "y";
Field[4].FY = "x";
Printf("%g", FieldValue(4, 1, 2, 0));     // expect: 12
// LonLat on a unit sphere: F2 sees (longitude, latitude, 0) in radians.
Field[5] = LonLat;
Field[5].InField = 2;
Field[5].RadiusStereo = 1;
Printf("%.6f", FieldValue(5, 0, 1, 0));   // expect: 1.570796
Printf("%.6f", FieldValue(5, 0, 0, 1));   // expect: 15.707963
Printf("%.6f", FieldValue(5, -1, 0, 0));  // expect: 3.141593
// FromStereo: (x, y) are 2R stereographic coordinates; (2, 0) is on the equator at lon 0.
Field[5].FromStereo = 1;
Printf("%.6f", FieldValue(5, 2, 0, 123));  // expect: 0.000000
Printf("%.6f", FieldValue(5, 0, 0, 0));    // expect: 15.707963
