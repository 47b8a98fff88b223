// Extruding a surface: its top copy is renumbered after the lateral surfaces, the volume
// takes its tag as if Geometry.OldNewReg were 0, and Boundary{Volume{}} lists the source
// (reversed), the top and the lateral surfaces. Surface Loop and Volume are entities that
// Physical Volume and the next-tag variables see. Expectations: gmsh 4.8.4 -0.
Macro P
 n = #L[];
 For i In {0:n-1}
  Printf("L %g %g", i, L[i]);
 EndFor
Return
Point(1) = {0,0,0,0.1}; Point(2) = {1,0,0,0.1}; Point(3) = {1,1,0,0.1}; Point(4) = {0,1,0,0.1};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};
L[] = Extrude {0,0,1} { Surface{1}; Layers{{2,3},{0.5,1}}; }; Call P;
Printf("newp %g newl %g news %g newreg %g newv %g newsl %g", newp, newl, news, newreg, newv, newsl);
L[] = Boundary{Surface{L[0]};}; Call P;
L[] = Boundary{Volume{1};}; Call P;
Point{4} In Volume{1};
Physical Volume("box", 7) = {1};
L[] = Physical Volume{7}; Call P;
Surface Loop(40) = {1, 26, 13, 17, 21, 25};
Volume(41) = {40};
Printf("newv %g newsl %g newreg %g", newv, newsl, newreg);
Geometry.OldNewReg = 0;
Printf("newv %g newsl %g", newv, newsl);
L[] = Volume{:}; Call P;
// expect: L 0 26
// expect: L 1 1
// expect: L 2 13
// expect: L 3 17
// expect: L 4 21
// expect: L 5 25
// expect: newp 15 newl 27 news 27 newreg 27 newv 27 newsl 27
// expect: L 0 6
// expect: L 1 7
// expect: L 2 8
// expect: L 3 9
// expect: L 0 -1
// expect: L 1 26
// expect: L 2 13
// expect: L 3 17
// expect: L 4 21
// expect: L 5 25
// expect: L 0 1
// expect: newv 42 newsl 42 newreg 42
// expect: newv 42 newsl 41
// expect: L 0 1
// expect: L 1 41
