// Gradation on the unit sphere: a 0.01 ball of radius 0.05 at (1,0,0) in a
// 0.3 background, limited to |grad h| <= 0.2 on a 2-degree grid. Checked
// along the equator: never above the input, the growth bounded by the rate
// (10% slack for the 8-neighbour path), and the cone near the source.
Field[1] = MathEval;
Field[1].F = "0.3";
Field[2] = Ball;
Field[2].XCenter = 1;  Field[2].Radius = 0.05;  Field[2].VIn = 0.01;  Field[2].VOut = 0.3;
Field[3] = Min;
Field[3].FieldsList = {1, 2};
Field[4] = Gradation;
Field[4].InField = 3;
Field[4].Rate = 0.2;
Field[4].Resolution = 2;
Printf("%g", FieldValue(4, 1, 0, 0));   // expect: 0.01
n = 90;
For i In {0 : n - 1}
  a = i * Pi / n;  b = (i + 1) * Pi / n;
  ha = FieldValue(4, Cos(a), Sin(a), 0);
  hb = FieldValue(4, Cos(b), Sin(b), 0);
  Assert(ha <= FieldValue(3, Cos(a), Sin(a), 0) + 1e-12, "above the input at %g deg", a * 180 / Pi);
  chord = 2 * Sin((b - a) / 2);
  Assert(Fabs(hb - ha) <= 0.2 * chord * 1.1, "growth %g over %g at %g deg", hb - ha, chord, a * 180 / Pi);
EndFor
// 60 degrees away (chord 1): about 0.01 + 0.2 (1 - 0.05), far below the input's 0.3.
h60 = FieldValue(4, Cos(Pi / 3), Sin(Pi / 3), 0);
Assert(h60 > 0.19 && h60 < 0.23, "h(60 deg) = %g", h60);
// Opposite side: the background 0.3 again.
Printf("%g", FieldValue(4, -1, 0, 0));   // expect: 0.3
