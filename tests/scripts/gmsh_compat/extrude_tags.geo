// Extrude takes new tags in Gmsh 4.8.4's order and returns, per extruded entity, its top,
// then its body, then (Geometry.ExtrudeReturnLateralEntities) the lateral entities; the
// coherence that ends each extrusion merges the copies' points and the swept curves that
// already exist, and newp/newl follow the largest tags left. Expectations: gmsh 4.8.4 -0.
Macro P
 n = #L[];
 For i In {0:n-1}
  Printf("L %g %g", i, L[i]);
 EndFor
Return
Point(1) = {0,0,0,0.1}; Point(2) = {1,0,0,0.1}; Point(3) = {1,1,0,0.1};
Line(1) = {1,2}; Line(2) = {2,3};
// Two curves: the second shares the swept line of point 2 with the first.
L[] = Extrude {0,0,1} { Curve{1,2}; }; Call P;
Printf("newp %g newl %g news %g newreg %g", newp, newl, news, newreg);
// A point whose sweep already exists: only its top is returned.
L[] = Extrude {0,0,1} { Point{3}; }; Call P;
// A rotation about an axis through point 1: a triangle with a circle arc.
L[] = Extrude {{0,0,1},{0,0,0},Pi/2} { Curve{1}; Layers{4}; Recombine; }; Call P;
o3[] = L[];
L[] = Extrude {{0,0,1},{0,0,0},Pi} { Point{2}; }; Call P;
L[] = Boundary{Surface{o3[1]};}; Call P;
Printf("newp %g newl %g news %g newreg %g", newp, newl, news, newreg);
// A twist: a spline through Geometry.ExtrudeSplinePoints steps.
L[] = Extrude {{0,0,1},{1,0,0},{0,0,0},Pi/2} { Point{3}; }; Call P;
Printf("newp %g newl %g news %g newreg %g", newp, newl, news, newreg);
xyz[] = Point{newp-1}; Printf("xyz %.6g %.6g %.6g", xyz[0], xyz[1], xyz[2]);
Geometry.ExtrudeReturnLateralEntities = 0;
Point(100) = {5,0,0,0.1}; Point(101) = {6,0,0,0.1}; Line(100) = {100,101};
L[] = Extrude {0,1,0} { Curve{100}; }; Call P;
// expect: L 0 3
// expect: L 1 6
// expect: L 2 5
// expect: L 3 -4
// expect: L 4 7
// expect: L 5 10
// expect: L 6 9
// expect: L 7 -5
// expect: newp 8 newl 11 news 11 newreg 11
// expect: L 0 7
// expect: L 0 11
// expect: L 1 13
// expect: L 2 12
// expect: L 0 10
// expect: L 1 14
// expect: L 0 1
// expect: L 1 12
// expect: L 2 -11
// expect: newp 11 newl 15 news 15 newreg 15
// expect: L 0 15
// expect: L 1 15
// expect: newp 16 newl 16 news 16 newreg 16
// expect: xyz 1 -0.531375 1.73138
// expect: L 0 101
// expect: L 1 104
