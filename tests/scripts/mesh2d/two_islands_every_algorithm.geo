// Regression: a C-shaped island with a small island in its bay, 0.026 from the
// bay's wall, closer than the size 0.15 (the case of a repaired 1D mesh). Reported as a front2d
// failure ("mesh size must be positive and finite (got inf at (inf, inf))") where del2d
// and meshadapt meshed it: every algorithm must mesh it, above the quality floor.
h = 0.15;
Point(1) = {-1, -1, 0, h}; Point(2) = {1, -1, 0, h}; Point(3) = {1, 1, 0, h}; Point(4) = {-1, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
// The C: an annular sector open towards +x (from 40 to 320 degrees).
Point(10) = {0, 0, 0, h};
a0 = 40 * Pi / 180; a1 = 320 * Pi / 180; am = Pi;
Point(11) = {0.4 * Cos(a0), 0.4 * Sin(a0), 0, h};
Point(12) = {0.4 * Cos(am), 0.4 * Sin(am), 0, h};
Point(13) = {0.4 * Cos(a1), 0.4 * Sin(a1), 0, h};
Point(14) = {0.25 * Cos(a1), 0.25 * Sin(a1), 0, h};
Point(15) = {0.25 * Cos(am), 0.25 * Sin(am), 0, h};
Point(16) = {0.25 * Cos(a0), 0.25 * Sin(a0), 0, h};
Circle(11) = {11, 10, 12}; Circle(12) = {12, 10, 13};
Line(13) = {13, 14};
Circle(14) = {14, 10, 15}; Circle(15) = {15, 10, 16};
Line(16) = {16, 11};
Curve Loop(2) = {11, 12, 13, 14, 15, 16};
// The small island, radius 0.024, 0.026 from the bay's wall.
cx = -0.2; cy = 0; r = 0.024;
Point(20) = {cx, cy, 0, h};
Point(21) = {cx + r, cy, 0, h}; Point(22) = {cx, cy + r, 0, h}; Point(23) = {cx - r, cy, 0, h}; Point(24) = {cx, cy - r, 0, h};
Circle(21) = {21, 20, 22}; Circle(22) = {22, 20, 23}; Circle(23) = {23, 20, 24}; Circle(24) = {24, 20, 21};
Curve Loop(3) = {21, 22, 23, 24};
Plane Surface(1) = {1, 2, 3};
algos[] = {6, 5, 1};   // front2d, del2d, meshadapt
For i In {0:2}
  Mesh.Algorithm = algos[i];
  Mesh 2;
  Printf("%g %d", algos[i], Mesh.StatsRhoMin >= 0.3);
EndFor
// expect: 6 1
// expect: 5 1
// expect: 1 1
// compare_with_gmsh: skip (Mesh.StatsRhoMin is ours)
