// Partitions are made of the 2D mesh: asked for with only Mesh 1, an error at Mesh 1.
Mesh.NbPartitions = 2;
Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3}; Point(3) = {1, 1, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh 1;   // expect error: 7:1: invalid-option-value
// compare_with_gmsh: skip
