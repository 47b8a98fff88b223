// Embedded points and curves size their neighbourhood: the face around them gets their 1D
// sizes extended, as the boundary's: 5428 triangles here, 2654 in Gmsh 4.8.4, whose
// refinement takes a triangle's size as the mean of its three vertices' (an embedded point
// weighs a third), where ours takes the size at the circumcentre; 242 without them.
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1:4}; Plane Surface(1) = {1};
Point(5) = {0.3, 0.5, 0, 0.005};
Point {5} In Surface {1};
Point(6) = {0.6, 0.2, 0, 0.01}; Point(7) = {0.8, 0.8, 0, 0.01};
Line(5) = {6, 7};
Curve {5} In Surface {1};
Mesh 2;
Printf("more than 4 times the 242 triangles without them: %g", Mesh.NbTriangles > 4 * 242);  // expect: more than 4 times the 242 triangles without them: 1
