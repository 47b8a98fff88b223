// A filling Surface with a hole (Gmsh 4.8.4 accepts it: the first loop, of 3 or 4 curves,
// is the patch, the others are holes, as in its benchmarks/2d/ruled_on_sphere.geo).
// Boundary lists the patch's loop as is, then the hole reversed, as for a Plane Surface.
Point(1) = {0, 0, 0, 0.3}; Point(2) = {3, 0, 0.5, 0.3}; Point(3) = {3, 3, 0, 0.3}; Point(4) = {0, 3, 0.5, 0.3};
Point(5) = {1, 1, 0.25, 0.3}; Point(6) = {2, 1, 0.25, 0.3}; Point(7) = {1.5, 2, 0.25, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7};
Surface(1) = {1, 2};
b[] = Boundary{Surface{1};};
Printf("%g: %g %g %g %g %g %g %g", #b[], b[0], b[1], b[2], b[3], b[4], b[5], b[6]);
Printf("%g", news);
// gmsh 4.8.4 -0 output:
// expect: 7: 1 2 3 4 -7 -6 -5
// expect: 8
// Meshed in the patch's parameters (non-planar: z = 0, 0.5, 0, 0.5 at the corners), the
// hole's nodes projected onto the patch. `gmsh -2`: 292 triangles; ours within 15%.
Mesh 2;
Printf("%g", Fabs(Mesh.NbTriangles - 292) <= 0.15 * 292);
// expect: 1
