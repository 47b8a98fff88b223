// Gmsh's display statements (Color, Hide, Show, Recursive Hide/Show, View) change only what
// its window shows: each kind is parsed, skipped and noted once (display-only), and the
// script runs on (they stopped the run before).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Color Red{ Surface{1}; }
Color {0, 128, 255} { Curve{1, 2}; }
Hide { Point{1}; }
Show "*";
Hide "*";
Recursive Show { Surface{1}; }
Recursive Hide { Curve{3}; }
View "v" { ST(0, 0, 0, 1, 0, 0, 0, 1, 0){1, 2, 3}; };
s[] = Surface{:};
Printf("after the display statements: %g surface", #s[]);
// expect: after the display statements: 1 surface
