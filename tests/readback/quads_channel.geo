// A channel of quadrangles for the read-back checks (quads_readers.py): a transfinite
// recombined reach (structured quadrangles) joined to a recombined unstructured basin
// (mostly quadrangles, perhaps a few triangles), written as MSH 4.1, MSH 2.2, VTK, UGRID
// and SCHISM hgrid.gr3. OutDir is set by the test.
DefineConstant[ OutDir = "." ];
Point(1) = {0, 0, 0, 0.25}; Point(2) = {4, 0, 0, 0.25}; Point(3) = {4, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
Point(5) = {6, -1, 0, 0.25}; Point(6) = {6, 2, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 21;
Transfinite Curve{2, 4} = 6 Using Bump 0.5;
Transfinite Surface{1};
Recombine Surface{1, 2};
Physical Surface("water") = {1, 2};
Physical Curve("open") = {4};
Physical Curve("land") = {1, 3, 5, 6, 7};
Mesh 2;
Printf("quadrangles %g triangles %g", Mesh.NbQuadrangles, Mesh.NbTriangles);
Save StrCat(OutDir, "/channel.msh");
Mesh.MshFileVersion = 2.2;
Save StrCat(OutDir, "/channel22.msh");
Save StrCat(OutDir, "/channel.vtk");
Save StrCat(OutDir, "/channel.nc");
Save StrCat(OutDir, "/hgrid.gr3");
