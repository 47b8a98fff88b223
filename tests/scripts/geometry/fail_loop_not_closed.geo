// A curve loop whose curves do not chain: the error names the curve where the chain
// breaks and a note points at the statement that created it.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
// expect error: 11:1: loop-not-closed
