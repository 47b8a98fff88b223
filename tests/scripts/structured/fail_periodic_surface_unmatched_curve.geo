// Periodic Surface with a transform pairs every curve of the target, embedded ones
// included, with the source curve the map takes onto it: surface 2's diagonal runs from
// its corner 12 to 14, the image of no curve of surface 1 (whose diagonal joins 1 and 3).
// Refused at the target list, naming curve 15.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1}; Line(5) = {1, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Curve{5} In Surface{1};
Point(11) = {2, 0, 0}; Point(12) = {3, 0, 0}; Point(13) = {3, 1, 0}; Point(14) = {2, 1, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11}; Line(15) = {12, 14};
Curve Loop(2) = {11, 12, 13, 14}; Plane Surface(2) = {2}; Curve{15} In Surface{2};
Periodic Surface {2} = {1} Translate {2, 0, 0};
// expect error: 11:18: invalid-operation
