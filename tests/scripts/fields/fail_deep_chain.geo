// Field references nested deeper than 1000 levels are refused before the
// build (whose recursion would otherwise overflow the stack).
Field[1] = MathEval;
Field[1].F = "1";
For i In {2:1200}
  Field[i] = MathEval;
  Field[i].F = Sprintf("F%g + 1", i - 1);
EndFor
Printf("%g", FieldValue(900, 0, 0, 0));   // expect: 900
h = FieldValue(1200, 0, 0, 0);
// expect error: 10:5: limit-exceeded
