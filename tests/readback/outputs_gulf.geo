// The Gulf of Mexico (examples/gulf_of_mexico.geo, coarser: 30 km on the coast), a regional
// sea with open boundaries and islands, meshed once and saved in every mesh format for
// outputs_agree.py (see outputs_world.geo). OutDir is set by the test.
DefineConstant[ OutDir = "." ];
ShoreSizeMin = 30e3;
Include "../../examples/gulf_of_mexico.geo";
Mesh 2;
Save StrCat(OutDir, "/out.msh");
Save StrCat(OutDir, "/out.vtk");
Save StrCat(OutDir, "/out.nc");
Save StrCat(OutDir, "/fort.14");
Save StrCat(OutDir, "/hgrid.gr3");
Mesh.MshFileVersion = 2.2;
Save StrCat(OutDir, "/out22.msh");
