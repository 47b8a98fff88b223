// A Line from a point to itself: Gmsh keeps a degenerate curve with no mesh elements; we
// create no curve but take its tag, with a warning.
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 2};
Printf("%g", newl);  // expect: 3
Line(newl) = {2, 1};
Printf("%g", newl);  // expect: 4
// expect warning: 6:1: gmsh-compat: line 2 goes from point 2 to itself: Gmsh keeps it as a degenerate curve with no mesh elements; we do not create it (only its tag is taken)
