// PartitionMesh with more partitions than triangles: an error at the statement.
Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3}; Point(3) = {1, 1, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 2;
PartitionMesh 1000;   // expect error: 7:1: invalid-option-value: Mesh.NbPartitions = 1000: 1000 partitions of 17 2D elements: give between 1 and 17
// compare_with_gmsh: skip
