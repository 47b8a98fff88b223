// Intersect Curve{..} Surface{s}: a new point (tag newp) where each curve meets a filling
// Surface, found as Gmsh finds it (Newton from the middle of the curve and of the patch,
// which may land on the curve's extension: line 6 stops at z = 1 and still gets a point,
// as in Gmsh). Here a 4-sided patch of the plane z = 0 and a sphere octant (3 sides In Sphere).
Point(1) = {0, 0, 0, 0.1}; Point(2) = {2, 0, 0, 0.1}; Point(3) = {2, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Point(5) = {0.3, 0.4, -1, 0.2}; Point(6) = {0.5, 0.6, 3, 0.2};
Line(5) = {5, 6};
Point(7) = {0.3, 0.4, 1}; Point(8) = {0.5, 0.6, 3};
Line(6) = {7, 8};
p[] = Intersect Curve {5, 6} Surface {1};
Printf("%g points, first %g", #p[], p[0]);
For i In {0:#p[] - 1}
  c[] = Point{p[i]};
  Printf("%.6f %.6f %.6f", c[0], c[1], c[2]);
EndFor
r = 10;
Point(11) = {0, 0, 0, 1}; Point(12) = {r, 0, 0, 1}; Point(13) = {0, r, 0, 1}; Point(14) = {0, 0, r, 1};
Circle(11) = {12, 11, 13}; Circle(12) = {13, 11, 14}; Circle(13) = {14, 11, 12};
Curve Loop(11) = {11, 12, 13};
Surface(11) = {11} In Sphere {11};
Point(15) = {8, 5, 9, 1};
Line(15) = {11, 15};
q[] = Intersect Curve {15} Surface {11};
c[] = Point{q[0]};
Printf("%g: %.6f %.6f %.6f, radius %.6f", q[0], c[0], c[1], c[2], Sqrt(c[0]^2 + c[1]^2 + c[2]^2));
// gmsh 4.8.4 -0 output:
// expect: 2 points, first 9
// expect: 0.350000 0.450000 0.000000
// expect: 0.200000 0.300000 0.000000
// expect: 16: 6.135720 3.834825 6.902685, radius 10.000000
