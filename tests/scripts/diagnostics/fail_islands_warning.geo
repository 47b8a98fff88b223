// Three closed B-splines far below the mesh size 0.1 in a unit square: each gets 2 mesh
// edges and is left out, reported as ONE mesh-warning for the surface at `Mesh 2;`.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
centres[] = {0.3, 0.3, 0.004,  0.7, 0.3, 0.012,  0.5, 0.7, 0.006};
For k In {0:2}
  p = 10 + 4 * k;
  For i In {0:3}
    Point(p + i) = {centres[3 * k] + centres[3 * k + 2] * Cos(Pi / 2 * i),
                    centres[3 * k + 1] + centres[3 * k + 2] * Sin(Pi / 2 * i), 0, 0.1};
  EndFor
  BSpline(10 + k) = {p, p + 1, p + 2, p + 3, p};
  Curve Loop(2 + k) = {10 + k};
EndFor
Plane Surface(1) = {1, 2, 3, 4};
Printf("before");   // expect: before
Mesh 2;             // expect warning: 19:1: mesh-warning: surface 1: 3 islands smaller than the mesh size are left out (their closed curves got fewer than 3 mesh edges; largest near (0.7, 0.3, 0)): hole loops 2, 3, 4
Printf("%g", Mesh.NbTriangles > 0);   // expect: 1
