// A list of depth grids by priority whose depth variables disagree on units (m and km)
// is refused at the FileName statement, before meshing.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {0, 1, 0, 0.2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Bathymetry;
Field[1].FileName = "../../data/grids/depth_m.nc, ../../data/grids/depth_km.nc";
Field[1].Positive = "down";
Mesh.DepthField = 1;
Mesh 2;
// expect error: 12:1: bad-field-value
