// The Gulf of Mexico example meshed once and saved twice, as MSH and as UGRID netCDF, with
// ETOPO depths at the nodes (Mesh.DepthField): ugrid_netcdf4.py reads both back and
// compares them. OutDir is set by the test.
DefineConstant[ OutDir = "." ];
Include "../../examples/gulf_of_mexico.geo";
depth = newf;
Field[depth] = Bathymetry;
Field[depth].FileName = StrCat(BathyDir, "etopo5_global_0.25deg.nc");
Field[depth].Output = "depth";
Field[depth].MinDepth = 5;
Mesh.DepthField = depth;
Mesh 2;
Save StrCat(OutDir, "/gulf.msh");
Save StrCat(OutDir, "/gulf.nc");
