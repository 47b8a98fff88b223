// The Gulf of Mexico example with Mesh.NodeData: depth, size and criterion at the nodes,
// meshed once and saved as MSH 4.1, binary MSH 2.2, VTK and UGRID: node_data_readers.py
// reads each back with another program's reader. OutDir is set by the test.
DefineConstant[ OutDir = "." ];
Include "../../examples/gulf_of_mexico.geo";
Mesh.NodeData = "depth,size,criterion";
Mesh 2;
Save StrCat(OutDir, "/gulf41.msh");
Mesh.MshFileVersion = 2.2;
Mesh.Binary = 1;
Save StrCat(OutDir, "/gulf22b.msh");
Mesh.Binary = 0;
Save StrCat(OutDir, "/gulf.vtk");
Save StrCat(OutDir, "/gulf.nc");
