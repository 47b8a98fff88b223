// A hole that crosses the outer loop of a non-planar filling Surface: the crossing is
// found in the patch's parameters and reported where it is, on the hole's line.
Point(1) = {0, 0, 0, 0.3}; Point(2) = {3, 0, 0.5, 0.3}; Point(3) = {3, 3, 0, 0.3}; Point(4) = {0, 3, 0.5, 0.3};
Point(5) = {1, 1, 0.25, 0.3}; Point(6) = {4, 1, 0.25, 0.3}; Point(7) = {1.5, 2, 0.25, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7};
Surface(1) = {1, 2};
Mesh 2;
// expect error: 10:1: mesh-error: surface 1: boundary edges of curves 5 and 2 cross near (2.8, 1, 0.25)
