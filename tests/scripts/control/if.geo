// If / ElseIf / Else / EndIf, nested and on one line.
x = 2;
If (x == 1)
  Printf("one");
ElseIf (x == 2)
  Printf("two");
Else
  Printf("other");
EndIf
If (0)
  Printf("no");
EndIf
If (1) Printf("inline"); EndIf
If (x > 0)
  If (x > 1)
    Printf("nested %g", x);
  Else
    Printf("not here");
  EndIf
EndIf
If (0)
  Printf("a");
ElseIf (0)
  Printf("b");
ElseIf (x)
  Printf("c");
Else
  Printf("d");
EndIf
If (x - 2)
  Printf("zero is false");
Else
  Printf("else branch");
EndIf
// gmsh 4.8.4 -0 output:
// expect: two
// expect: inline
// expect: nested 2
// expect: c
// expect: else branch
