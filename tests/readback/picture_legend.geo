// A square bay with three physical curve groups (coast, open, river) meshed once and drawn
// as SVG whole and zoomed (Mesh.PictureBox, x and y bounds in the plane), coloured by
// quality and by size: picture_legend.py reads the SVGs back with Python's XML parser.
// OutDir is set by the test.
DefineConstant[ OutDir = "." ];
Point(1) = {0, 0, 0, 0.08}; Point(2) = {1, 0, 0, 0.08}; Point(3) = {1, 1, 0, 0.02};
Point(4) = {0, 1, 0, 0.08};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("coast") = {1, 4};
Physical Curve("open") = {2};
Physical Curve("river & <mouth>") = {3};
Physical Surface("sea") = {1};
Mesh 2;
Mesh.PictureWidth = 600;
Mesh.PictureWorst = 3;
Save StrCat(OutDir, "/whole.svg");
Mesh.PictureBox = {0.5, 1, 0.5, 1};
Mesh.PictureColour = 2;
Save StrCat(OutDir, "/zoom.svg");
