// A transform that does not take the source's end points onto the target's is refused
// at its statement (Gmsh checks the same, within Geometry.Tolerance of the model's size).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(3) = {3, 4};
Periodic Curve {3} = {1} Translate {0, 2, 0};   // expect error: 5:1: invalid-operation
