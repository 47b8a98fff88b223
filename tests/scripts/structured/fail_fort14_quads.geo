// ADCIRC's fort.14 holds triangles only: a recombined mesh is refused before anything is
// written (SCHISM's hgrid.gr3 holds the quadrangles).
Point(1) = {0, 0, 0, 0.25}; Point(2) = {1, 0, 0, 0.25}; Point(3) = {1, 1, 0, 0.25}; Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Recombine Surface{1};
Field[1] = MathEval; Field[1].F = "10";
Mesh.DepthField = 1;
Mesh 2;
Save "quads_refused.14";   // expect error: 11:6: file-write-error
// compare_with_gmsh: skip
