// A unit square with transfinite curves, a recombined surface and physical groups.
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(5) = {1, 2, 3, 4};
Plane Surface(6) = {5};
Transfinite Curve{1, 3} = 11 Using Progression 1.1;
Transfinite Curve{2, -4} = 11;
Transfinite Surface{6} = {1, 2, 3, 4} Alternate;
Recombine Surface{6};
MeshSize{1, 2} = lc / 2;
Physical Point(1) = {1};
Physical Line(2) = {1:4};
Physical Surface("domain") = {6};
Mesh 2;
Save "square.msh";
