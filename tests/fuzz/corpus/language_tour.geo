// Language features: variables, lists, ranges, names with ~{}, strings,
// control flow, macros, DefineConstant, options, Printf forms.
DefineConstant[ nx = 4, ny = {3, Name "Parameters/ny", Min 1, Max 10, Step 1}, title = "demo" ];
a = 5; b = a++; c = -2^2; d = 2^3^2; e = 7 % 3; f = 6 | 1; g = (a > 3) ? 10 : 20;
L[] = {1:10:3, 20}; L[] += {30}; L[] -= {4}; L[1] = 99; L({0:1}) = {7, 8};
M() = -{1, 2} * 3;
Printf("sizes %g %g", #L[], #M());
Printf("L", L[]);
For i In {1:3}
  x~{i} = i^2;
  If (i == 2)
    Printf("two: %g", x~{i});
  ElseIf (i > 2)
    Printf("more: %g", x~{i});
  Else
    Printf("one");
  EndIf
EndFor
For (1:2) a += 1; EndFor
s = StrCat(title, "-", Sprintf("%03.0f", a));
Printf("%s has %g chars", s, StrLen(s));
Macro Square
  sq = v * v;
Return
v = 12; Call Square; Printf("%g", sq);
Call "Square";
If (Exists(x~{3}) && !Exists(y))
  Printf("x_3 = %g", x_3);
EndIf
S[] = Str("one", "two");
Printf("%s", S[1]) > "out.txt";
Mesh.Algorithm = 5; Mesh.Smoothing++; General.Verbosity = 2;
Printf("alg %g", Mesh.Algorithm);
u = Unique({3, 1, 3, 2}); h = Hypot(3, 4); r = Round(2.5); m = Max(1, Min(5, 3));
Delete a;
Assert(h == 5, "hypot is %g", h);
