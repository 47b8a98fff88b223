// More partitions than the mesh has triangles: refused at the Mesh statement, with the
// assignment as a note.
Mesh.NbPartitions = 100000;
Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3}; Point(3) = {1, 1, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 2;   // expect error: 8:1: invalid-option-value: Mesh.NbPartitions = 100000: 100000 partitions of 17 2D elements: give between 1 and 17
// compare_with_gmsh: skip
