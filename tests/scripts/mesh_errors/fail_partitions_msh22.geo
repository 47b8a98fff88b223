// A partitioned mesh in MSH 2.2 (its partition tags are not written): an error at the
// file name; MSH 4.1 holds them.
Mesh.NbPartitions = 2;
Mesh.MshFileVersion = 2.2;
Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3}; Point(3) = {1, 1, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 2;
Save "partitioned.msh";   // expect error: 10:6: partitions-not-held
// compare_with_gmsh: skip
