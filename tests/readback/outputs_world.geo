// The World Ocean (examples/world_ocean.geo at a coarse setting: GSHHG low coarsened to
// 100 km, 200 km on the coasts, the 1-degree ETOPO5 grid; two islands are smaller than the
// mesh size there, and the 2D mesher leaves them out with a warning) meshed
// once and saved in every mesh format: outputs_agree.py reads each back with another
// program's reader and checks that they hold the same nodes in the same order, the same
// triangles, no node outside them, and boundary lists that close. OutDir is set by the test.
DefineConstant[ OutDir = "." ];
CoastAccuracy = 100e3;
ShoreSizeMin = 200e3;
CoastResolution = "l";   // GSHHG low from the system
CoastMinArea = 0;
BathyName = "etopo5_global_1deg.nc";
Quiet = 1;
Include "../../examples/world_ocean.geo";
Mesh 2;
Save StrCat(OutDir, "/out.msh");
Save StrCat(OutDir, "/out.vtk");
Save StrCat(OutDir, "/out.nc");
Save StrCat(OutDir, "/fort.14");
Save StrCat(OutDir, "/hgrid.gr3");
Mesh.MshFileVersion = 2.2;
Save StrCat(OutDir, "/out22.msh");
