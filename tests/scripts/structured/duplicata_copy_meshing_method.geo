// Geometry.CopyMeshingMethod 1: Duplicata copies the transfinite laws of the curves and the
// transfinite and recombine settings of the surfaces, as Gmsh 4.8.4 does (its benchmark
// copy_mesh_spec_with_duplicata.geo); with 0 the copy is meshed by the sizes alone.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 0.8, 0, 0.5}; Point(4) = {0, 0.8, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(5) = {1, 2, 3, 4};
Plane Surface(6) = {5};
Transfinite Curve{1, 3} = 10;
Transfinite Curve{2, 4} = 7 Using Progression 1.2;
Transfinite Surface{6};
Recombine Surface{6};
Geometry.CopyMeshingMethod = 1;
Translate{2, 0, 0} { Duplicata{ Surface{6}; } }
Geometry.CopyMeshingMethod = 0;
Translate{4, 0, 0} { Duplicata{ Surface{6}; } }
Mesh 2;
Printf("%g nodes, %g triangles, %g quadrangles", Mesh.NbNodes, Mesh.NbTriangles, Mesh.NbQuadrangles);
// expect: 151 nodes, 12 triangles, 108 quadrangles
