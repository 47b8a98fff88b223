// Extruding a curve that does not exist is an error at the Extrude (Gmsh skips it).
Point(1) = {0, 0, 0, 0.1};
Point(2) = {1, 0, 0, 0.1};
Line(1) = {1, 2};
Extrude {0, 0, 1} { Curve{1, 7}; }
// expect error: 5:1: missing-entity
