// Macro names given as strings, macros building strings and lists.
Macro "Greet"
  msg = StrCat("hello ", who);
Return
who = "ocean";
Call Greet;
Printf(msg);
Macro AddPoint
  pts[] += {px, py};
  np++;
Return
np = 0;
pts[] = {};
For t In {0:2}
  px = t;
  py = 2*t;
  Call AddPoint;
EndFor
Printf("%g", np);
Printf("pts", pts[]);
which = "Greet";
who = "sphere";
Call StrCat(which);
Printf(msg);
// gmsh 4.8.4 -0 output:
// expect: hello ocean
// expect: 3
// expect: pts [0]0 [1]0 [2]1 [3]2 [4]2 [5]4
// expect: hello sphere
