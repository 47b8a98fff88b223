// A square whose top and right sides copy the bottom and left (Periodic Curve, a
// translation and the sign's direction) for the read-back check periodic_readers.py:
// the $Periodic section of MSH 4.1 and 2.2 as Gmsh's reader loads it. OutDir is set by
// the test.
DefineConstant[ OutDir = "." ];
Point(1) = {0, 0, 0, 0.02}; Point(2) = {1, 0, 0, 0.2};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Periodic Curve {3} = {1} Translate {0, 1, 0};
Periodic Curve {2} = {-4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(1) = {1, 2, 3, 4};
Physical Surface(2) = {1};
Mesh 2;
Save StrCat(OutDir, "/square.msh");
Mesh.MshFileVersion = 2.2;
Save StrCat(OutDir, "/square22.msh");
