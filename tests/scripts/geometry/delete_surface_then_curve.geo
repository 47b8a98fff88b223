// Delete{ Surface{1}; Curve{4}; } deletes curve 4 too: Gmsh 4.8.4 keeps a curve only while
// it bounds a surface, not while a curve loop names it (tutorial t6 does this). Physical
// groups keep the deleted tags: the surface made again with tag 1 is in group "s" again.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(5) = {1, 2, 4};
Physical Surface("s", 6) = {1};
Delete{ Surface{1}; Curve{4}; }
c[] = Curve{:};
s[] = Surface{:};
Printf("%g curves, %g surfaces", #c[], #s[]);  // expect: 3 curves, 0 surfaces
Line(6) = {4, 1};
Curve Loop(2) = {1, 2, 3, 6};
Plane Surface(1) = {2};
Transfinite Surface{1};
g[] = Physical Surface{:};
m[] = Physical Surface{6};
Printf("groups %g, members %g", #g[], #m[]);  // expect: groups 1, members 1
Mesh 2;
Printf("%g nodes, %g triangles", Mesh.NbNodes, Mesh.NbTriangles);  // expect: 9 nodes, 8 triangles
