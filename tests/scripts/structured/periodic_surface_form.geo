// Gmsh's surface form of Periodic (as in its benchmarks/2d/periodic_rotation_on_axis.geo):
// "Periodic Surface slave {slave curves} = master {master curves};" with the curve lists
// given by Boundary and the surface tags by expressions. Surface 2 copies surface 1 by the
// translation its paired curves give; a Periodic Curve with a transform after it then
// gives curve 6 another source (curve 4, as Gmsh's last statement wins), and the script
// goes on; meshed, surface 2 has as many triangles as surface 1 (half of the total).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0}; Point(6) = {2, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
s = 2;
Periodic Surface s {Boundary{Surface{s};}} = 1 {Boundary{Surface{1};}};
Periodic Curve {6} = {4} Translate {2, 0, 0};
Printf("%g", newp);  // expect: 7
Mesh.MeshSizeMax = 0.1;
Mesh 2;
Printf("%g", Mesh.NbTriangles % 2);  // expect: 0
