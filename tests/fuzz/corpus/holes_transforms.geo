// Circles, holes, transforms, boundaries, embedding and deletion.
r = 0.2;
Point(1) = {0, 0, 0}; Point(2) = {r, 0, 0}; Point(3) = {0, r, 0};
Point(4) = {-r, 0, 0}; Point(5) = {0, -r, 0};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2} Plane{0, 0, 1};
Curve Loop(1) = {1:4};
Point(10) = {-1, -1, 0}; Point(11) = {1, -1, 0}; Point(12) = {1, 1, 0}; Point(13) = {-1, 1, 0};
Line(10) = {10, 11}; Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 10};
Curve Loop(2) = {10:13};
Plane Surface(1) = {2, 1};
p[] = Translate{0.5, 0, 0}{ Duplicata{ Point{1}; } };
Rotate{{0, 0, 1}, {0, 0, 0}, Pi/4}{ Point{p[0]}; }
b[] = Boundary{ Surface{1}; };
all[] = Curve{:};
Printf("boundary %g curves, %g in total", #b[], #all[]);
Point(20) = {0.5, 0.5, 0};
Point{20} In Surface{1};
Coherence;
Delete { Point{p[0]}; }
Recursive Delete { Surface{1}; }
