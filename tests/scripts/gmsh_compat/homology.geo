// Gmsh's (co)homology requests (tutorial/t14.geo) ask for bases of the mesh's (co)homology
// spaces, which Gmsh adds to the mesh as physical groups: each of Gmsh 4.8.4's forms is
// parsed, its lists evaluated, and the request skipped with one note per run
// (homology-skipped); the script runs on (t14.geo stopped at parse before). Output: gmsh
// 4.8.4 -0.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Physical Surface(10) = {1};
Physical Curve(11) = {1, 2};
Homology;
Homology {10};
Homology {{10}, {11}};
Cohomology {{10}, {11}};
Homology ({0, 1}) {{10}, {11}};
Cohomology (1) {10, 11};
Betti {10};
Printf("after the homology requests");
// expect: after the homology requests
