// A tag that is already taken in its dimension (curves and points have separate tags).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(2) = {1, 2};
For i In {1:3}
  Point(i + 1) = {i, 1, 0};
EndFor
// expect error: 6:3: duplicate-tag
