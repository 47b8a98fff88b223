// A hole that lies outside the outer loop of its plane surface.
Macro Square
  p = newp;
  Point(p) = {x, y, 0};
  Point(p + 1) = {x + s, y, 0};
  Point(p + 2) = {x + s, y + s, 0};
  Point(p + 3) = {x, y + s, 0};
  l = newl;
  Line(l) = {p, p + 1};
  Line(l + 1) = {p + 1, p + 2};
  Line(l + 2) = {p + 2, p + 3};
  Line(l + 3) = {p + 3, p};
  Curve Loop(l + 4) = {l:l + 3};
Return
x = 0; y = 0; s = 1;
Call Square;
outer = l + 4;
x = 5; s = 0.5;
Call Square;
Plane Surface(1) = {outer, l + 4};
// expect error: 20:1: hole-outside
