// A periodic curve whose source does not exist is refused at its statement.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(3) = {3, 4};
Periodic Curve {3} = {-2};   // expect error: 4:1: invalid-operation
