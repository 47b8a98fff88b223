// The Gulf of Mexico example (its ETOPO depths at the nodes: Mesh.DepthField) meshed once
// and saved twice, as MSH and as UGRID netCDF: ugrid_netcdf4.py reads both back and
// compares them. OutDir is set by the test.
DefineConstant[ OutDir = "." ];
Include "../../examples/gulf_of_mexico.geo";
Mesh 2;
Save StrCat(OutDir, "/gulf.msh");
Save StrCat(OutDir, "/gulf.nc");
