// Several independent syntax errors, each reported once.
x = 1 +;
Point(1) = {0, 0, 0}
Point(2) = {1, 0, 0};
y = (2 * 3;
For i In {1:3}
  z = i *;
EndFor
If (x > 1
  w = 2;
EndIf
L[] = {1, 2;
Line(3) = {1, 2}};
EndFor
Macro Open
  q = 1;
