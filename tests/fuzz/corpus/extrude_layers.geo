// Extrude seeds: translation, rotation, twist, Layers and Recombine, a swept surface.
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25}; Point(3) = {1, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(4) = {1, 2, 3}; Plane Surface(5) = {4};
a[] = Extrude {0, 0, 1} { Curve{1}; Layers{{2, 3}, {0.5, 1}}; Recombine; };
b[] = Extrude {{0, 0, 1}, {0, 0, 0}, Pi/2} { Point{3}; Layers{4}; };
c[] = Extrude {{0, 0, 1}, {1, 0, 0}, {0, 0, 0}, Pi/3} { Point{2}; };
d[] = Extrude {0, 0, -1} { Surface{5}; Layers{3}; Recombine; };
Surface Loop(50) = {5, d[0]};
Physical Volume(1) = {d[1]};
Mesh 2;
