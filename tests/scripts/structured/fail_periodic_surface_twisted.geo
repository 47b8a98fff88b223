// Periodic Surface pairs curves whose end points no rigid map takes onto each other (curve
// 5 is paired with curve 2 and curve 6 with curve 1: a translation fits the first pairs
// only, and no rotation fits them all); the statement is refused.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {3, 0, 0}; Point(6) = {4, 0, 0}; Point(7) = {4, 1, 0}; Point(8) = {3, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Periodic Surface 2 {5, 6, 7, 8} = 1 {2, 1, 3, 4};
// expect error: 10:1: invalid-operation
