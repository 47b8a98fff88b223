// Extruding Curve{-1} sweeps the reversed curve: Gmsh lists the curve itself among the lateral
// curves (it compares |c| with the tag as written), and Surface{-1} likewise; Boundary{Volume{}}
// lists the swept surfaces positive. Expectations: gmsh 4.8.4 -0.
Point(1) = {0,0,0,0.2}; Point(2) = {1,0,0,0.2}; Point(3) = {1,1,0,0.2}; Point(4) = {0,1,0,0.2};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Line(5) = {4,3}; Curve Loop(1) = {1,2,-5,4}; Plane Surface(1) = {1};
x[] = Extrude {0,0,-1} { Curve{-1}; Layers{2}; Recombine 0; };
n = #x[];
For i In {0:n-1}
 Printf("x %g", x[i]);
EndFor
v[] = Extrude {0,0,1} { Surface{-1}; };
n = #v[];
For i In {0:n-1}
 Printf("v %g", v[i]);
EndFor
b[] = Boundary{Volume{v[1]};};
n = #b[];
For i In {0:n-1}
 Printf("b %g", b[i]);
EndFor
Printf("%g %g %g %g", newp, newl, news, newv);
// expect: x 6
// expect: x 9
// expect: x -1
// expect: x 8
// expect: x -7
// expect: v 31
// expect: v 1
// expect: v 1
// expect: v 18
// expect: v 22
// expect: v 26
// expect: v 30
// expect: b -1
// expect: b 31
// expect: b 18
// expect: b 22
// expect: b 26
// expect: b 30
// expect: 17 32 32 32
