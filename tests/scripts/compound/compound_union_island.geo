// One island left out of a Compound Surface's union, named as the script wrote the
// compound (not by the union's own tag), in the singular.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {2, 0, 0, 0.1};
Point(4) = {2, 1, 0, 0.1}; Point(5) = {1, 1, 0, 0.1}; Point(6) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, -2};
For i In {0:3}
  Point(10 + i) = {0.3 + 0.005 * Cos(Pi / 2 * i), 0.4 + 0.005 * Sin(Pi / 2 * i), 0, 0.1};
EndFor
BSpline(10) = {10, 11, 12, 13, 10};
Curve Loop(3) = {10};
Plane Surface(1) = {1, 3};
Plane Surface(2) = {2};
Compound Surface{1, 2};
Mesh 2;   // expect warning: 17:1: mesh-warning: the union of Compound Surface{1, 2}: 1 island smaller than the mesh size is left out (its closed curve got fewer than 3 mesh edges; near (0.3, 0.4, 0)): hole loop 12
Printf("%g", Mesh.NbTriangles > 0);   // expect: 1
// compare_with_gmsh: skip (the words of a stereomesh warning)
