// The world test: every GSHHG crude coastline of world_c.txt as a closed BSpline
// through its points in unit-PolarSphere (u, v), Antarctica (curve loop 5) the outer
// loop of one Plane Surface and the 742 other coastlines its holes
// (tests/data/geo_scripts/make_world_geo.py wrote the model). The model must accept all
// of it: one surface, 743 loops, and the checks below (same values as gmsh 4.8.4 -0).
Include "../../data/geo_scripts/world_c.geo";
c[] = Curve{:};
s[] = Surface{:};
p[] = Point{:};
b[] = Boundary{ Surface{1}; };
If (#s[] != 1 || #b[] != 743 || #c[] != 743)
  Error("world_c: expected 1 surface bounded by 743 curves");
EndIf
Printf("%g curves, %g surface, %g boundary curves, %g points, newreg %g", #c[], #s[], #b[], #p[], newreg);
Printf("outer %g, first hole %g, last hole %g", b[0], b[1], b[742]);
// Antarctica's BSpline is closed: it starts and ends at its first point.
e[] = Boundary{ Curve{5}; };
Printf("Antarctica from %g to %g", e[0], e[1]);
x[] = Point{e[0]};
Printf("%.6f %.6f %.6f", x[0], x[1], x[2]);
x[] = Point{3};
Printf("%.6f %.6f %.6f", x[0], x[1], x[2]);
// gmsh 4.8.4 -0 output:
// expect: 743 curves, 1 surface, 743 boundary curves, 7158 points, newreg 744
// expect: outer 5, first hole -1, last hole -743
// expect: Antarctica from 2477 to 2477
// expect: -0.211005 0.000000 -0.977485
// expect: 0.299519 0.165125 0.939693
