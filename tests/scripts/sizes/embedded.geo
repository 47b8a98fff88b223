// Embedded points and curves size their neighbourhood: the face around them gets their 1D
// sizes extended, as the boundary's. Gmsh 4.8.4: 2654 triangles; here 3168, carried by the
// vertices as Gmsh does (5428 when each triangle took the size interpolated at its
// circumcentre in the boundary triangulation); 242 without them.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4}; Plane Surface(1) = {1};
Point(5) = {0.3, 0.5, 0, 0.005};
Point {5} In Surface {1};
Point(6) = {0.6, 0.2, 0, 0.01}; Point(7) = {0.8, 0.8, 0, 0.01};
Line(5) = {6, 7};
Curve {5} In Surface {1};
Mesh 2;
Printf("within 25 percent of gmsh's 2654 triangles: %g", Fabs(Mesh.NbTriangles - 2654) < 0.25 * 2654);  // expect: within 25 percent of gmsh's 2654 triangles: 1
