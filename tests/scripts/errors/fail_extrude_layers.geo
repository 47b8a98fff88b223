// Layers{{n1, n2}, {h1}}: as many heights as element counts are needed (Gmsh: "Wrong
// layer definition"), reported at the Layers.
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Line(1) = {1, 2};
Extrude {0, 1, 0} {
  Curve{1}; Layers{{2, 3}, {0.5}}; Recombine;
}
// expect error: 7:13: list-size-mismatch
