// The Gulf of Mexico example partitioned in 4 with METIS (Mesh.NbPartitions), meshed once
// and saved as partitioned MSH 4.1 (ASCII and binary), as one MSH file per part (Mesh.PartitionSplitMeshFiles),
// as VTK and as UGRID netCDF with the partition arrays: partitions_readers.py reads each
// back with another program's reader. OutDir is set by the test.
DefineConstant[ OutDir = "." ];
Include "../../examples/gulf_of_mexico.geo";
Mesh.NbPartitions = 4;
Mesh 2;
Save StrCat(OutDir, "/gulf.msh");
Save StrCat(OutDir, "/gulf.vtk");
Save StrCat(OutDir, "/gulf.nc");
Mesh.Binary = 1;
Save StrCat(OutDir, "/gulf_bin.msh");
Mesh.Binary = 0;
Mesh.PartitionSplitMeshFiles = 1;
Save StrCat(OutDir, "/split.msh");
