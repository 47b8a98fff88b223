// An algorithm number the kernel lacks: refused at the Mesh statement, with the assignment as a note.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.Algorithm = 7;
Mesh 2;
// expect error: 7:1: mesh-error: Mesh.Algorithm 7 is not available: use 1 (meshadapt), 2 (automatic), 3 (initial mesh only), 5 (del2d), 6 (front2d) or 8 (front2d for quadrangles)
// compare_with_gmsh: skip
