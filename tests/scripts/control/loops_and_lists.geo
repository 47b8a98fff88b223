// Loops over list indices, building lists and names in loops.
L[] = {10, 20, 30, 40};
sum = 0;
For k In {0:#L[]-1}
  sum += L[k];
EndFor
Printf("%g", sum);
squares[] = {};
For i In {1:5}
  squares[] += i^2;
EndFor
Printf("sq", squares[]);
For i In {1:3}
  For j In {i:3}
    pair~{i}~{j} = 10*i + j;
  EndFor
EndFor
Printf("%g %g %g", pair_1_1, pair_1_3, pair_3_3);
evens[] = {};
For i In {1:10}
  If (i % 2 == 0)
    evens[] += i;
  EndIf
EndFor
Printf("e", evens[]);
Printf("%g", #evens());
down[] = {};
For x In {1:0:-0.25}
  down[] += x;
EndFor
Printf("d", down[]);
Printf("%g", x);
// gmsh 4.8.4 -0 output:
// expect: 100
// expect: sq [0]1 [1]4 [2]9 [3]16 [4]25
// expect: 11 13 33
// expect: e [0]2 [1]4 [2]6 [3]8 [4]10
// expect: 5
// expect: d [0]1 [1]0.75 [2]0.5 [3]0.25 [4]0
// expect: -0.25
