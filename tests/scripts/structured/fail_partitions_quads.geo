// Partitions are made of triangles only so far: a recombined mesh with Mesh.NbPartitions
// is an error, not a partition that drops the quadrangles.
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25}; Point(3) = {1, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Recombine Surface{1};
Mesh.NbPartitions = 2;
Mesh 2;   // expect error: 9:1: invalid-option-value: Mesh.NbPartitions = 2: surface 1 has quadrangles, which are not partitioned yet (mesh it without Recombine, or set Mesh.NbPartitions = 0)
// compare_with_gmsh: skip
