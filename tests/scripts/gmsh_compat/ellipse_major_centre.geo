// An Ellipse whose major-axis point is its centre: Gmsh then takes the direction of the
// start point as the major axis; so do we, with a warning.
Point(1) = {0, 0, 0, 0.5};
Point(2) = {2, 0, 0, 0.5};
Point(3) = {0, 1, 0, 0.5};
Ellipse(1) = {2, 1, 1, 3};
// The arc from (2, 0) to (0, 1) with semi-axes 2 and 1 stays inside [0, 2] x [0, 1].
c[] = Curve In BoundingBox{-1e-3, -1e-3, -1e-3, 2.001, 1.001, 1e-3};
Printf("%g", #c[]);  // expect: 1
c[] = Curve In BoundingBox{-1e-3, -1e-3, -1e-3, 2.001, 0.99, 1e-3};
Printf("%g", #c[]);  // expect: 0
// expect warning: 6:1: gmsh-compat: ellipse 1: the major-axis point 1 is the centre: Gmsh then takes the direction of the start point 2 as the major axis, and so do we
