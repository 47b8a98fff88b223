// Chains of copies: surface 3 copies surface 2, which copies surface 1 (the statements in
// the other order: a copy waits for its source whatever the order), and surface 4 copies
// surface 3 by the curve-list form; all four have surface 1's triangles, although their
// own sizes would make them far coarser.
// 566 each (gmsh 4.8.4 -2: 578 each, 2312).
For i In {0 : 3}
  Point(4 * i + 1) = {2 * i, 0, 0, i ? 0.4 : 0.08}; Point(4 * i + 2) = {2 * i + 1, 0, 0, i ? 0.4 : 0.04};
  Point(4 * i + 3) = {2 * i + 1, 1, 0, i ? 0.4 : 0.08}; Point(4 * i + 4) = {2 * i, 1, 0, i ? 0.4 : 0.08};
  Line(4 * i + 1) = {4 * i + 1, 4 * i + 2}; Line(4 * i + 2) = {4 * i + 2, 4 * i + 3};
  Line(4 * i + 3) = {4 * i + 3, 4 * i + 4}; Line(4 * i + 4) = {4 * i + 4, 4 * i + 1};
  Curve Loop(i + 1) = {4 * i + 1, 4 * i + 2, 4 * i + 3, 4 * i + 4}; Plane Surface(i + 1) = {i + 1};
EndFor
Periodic Surface {3} = {2} Translate {2, 0, 0};
Periodic Surface {2} = {1} Translate {2, 0, 0};
Periodic Surface 4 {13, 14, 15, 16} = 3 {9, 10, 11, 12};
Mesh 2;
Printf("%g triangles", Mesh.NbTriangles);
// expect: 2264 triangles
