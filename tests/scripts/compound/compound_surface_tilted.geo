// Surfaces not in one plane: Gmsh 4.8.4 reparametrises their union; stereomesh meshes
// them one by one and says so at the Mesh statement.
// compare_with_gmsh: skip (a warning of ours)
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Point(5) = {2, 0, 0.5, 0.5}; Point(6) = {2, 1, 0.5, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Compound Surface{1, 2};
Compound Surface{7};   // expect warning: 11:1: gmsh-compat
Mesh 2;   // expect warning: 12:1: mesh-warning: Compound Surface{1, 2}: the surfaces are not in one plane (Gmsh reparametrises such a compound; stereomesh combines surfaces of one plane only); the surfaces are meshed one by one
Printf("%g", Mesh.NbTriangles > 0);   // expect: 1
