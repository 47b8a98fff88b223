// Copies that go round in a circle: surface 2 copies surface 1, surface 3 copies surface 2,
// and then surface 1 would copy surface 3 (Gmsh leaves all three unmeshed, waiting for
// each other); the last statement is refused at its place.
For i In {0 : 2}
  Point(4 * i + 1) = {2 * i, 0, 0}; Point(4 * i + 2) = {2 * i + 1, 0, 0};
  Point(4 * i + 3) = {2 * i + 1, 1, 0}; Point(4 * i + 4) = {2 * i, 1, 0};
  Line(4 * i + 1) = {4 * i + 1, 4 * i + 2}; Line(4 * i + 2) = {4 * i + 2, 4 * i + 3};
  Line(4 * i + 3) = {4 * i + 3, 4 * i + 4}; Line(4 * i + 4) = {4 * i + 4, 4 * i + 1};
  Curve Loop(i + 1) = {4 * i + 1, 4 * i + 2, 4 * i + 3, 4 * i + 4}; Plane Surface(i + 1) = {i + 1};
EndFor
Periodic Surface {2} = {1} Translate {2, 0, 0};
Periodic Surface {3} = {2} Translate {2, 0, 0};
Periodic Surface {1} = {3} Translate {-4, 0, 0};
// expect error: 13:1: invalid-operation
