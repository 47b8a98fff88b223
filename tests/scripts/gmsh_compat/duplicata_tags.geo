// Duplicata takes new tags in Gmsh 4.8.4's order: a copied surface takes its tag before its
// curves, each copied curve its tag before its points; Gmsh copies a shared point once per
// curve, the coherence after the Translate merges the copies, and newp follows the largest left.
Point(1) = {0,0,0,0.5}; Point(2) = {1,0,0,0.5}; Point(3) = {1,1,0,0.5}; Point(4) = {0,1,0,0.5};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(5) = {1,2,3,4}; Plane Surface(6) = {5};
d[] = Translate{0,2,0}{ Duplicata{ Surface{6}; } };
e[] = Boundary{Surface{d[0]};};
pp[] = Point{:};
cc[] = Curve{:};
Printf("d %g", d[0]);
For i In {0:#e[]-1}
 Printf("curve %g", e[i]);
 f[] = PointsOf{Curve{e[i]};};
 For j In {0:#f[]-1}
  Printf("  pt %g", f[j]);
 EndFor
EndFor
For i In {0:#pp[]-1}
 Printf("p %g", pp[i]);
EndFor
For i In {0:#cc[]-1}
 Printf("c %g", cc[i]);
EndFor
Printf("%g %g %g %g", newp, newl, newll, news);
g[] = Translate{0,2,0}{ Duplicata{ Curve{2}; } };
Printf("g %g", g[0]);
h[] = Duplicata{ Point{3}; };
Printf("h %g", h[0]);
// gmsh 4.8.4 -0 output:
// expect: d 7
// expect: curve 8
// expect:   pt 5
// expect:   pt 6
// expect: curve 9
// expect:   pt 6
// expect:   pt 10
// expect: curve 10
// expect:   pt 10
// expect:   pt 14
// expect: curve 11
// expect:   pt 14
// expect:   pt 5
// expect: p 1
// expect: p 2
// expect: p 3
// expect: p 4
// expect: p 5
// expect: p 6
// expect: p 10
// expect: p 14
// expect: c 1
// expect: c 2
// expect: c 3
// expect: c 4
// expect: c 8
// expect: c 9
// expect: c 10
// expect: c 11
// expect: 15 12 12 12
// expect: g 12
// expect: h 15
