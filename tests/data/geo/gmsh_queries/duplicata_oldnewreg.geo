// Next point tag after a transform's automatic Coherence merges points, with
// Geometry.OldNewReg = onr (run.sh runs it with onr = 1 and 0). Also Gmsh's own Duplicata
// numbering (each copied curve copies its control points AND its begin/end vertices again,
// without sharing between copied curves), which the kernel deliberately does not reproduce.
DefineConstant[ onr = 1 ];
Geometry.OldNewReg = onr;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};
Point(7) = {5, 5, 5}; Point(8) = {5, 5, 5};
Translate{0, 0, 0}{ Point{1}; }
Printf("onr=%g newp after coherence=%g", onr, newp);
Point(4) = {0, 1, 0}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
q[] = Duplicata{ Curve{1}; Curve{2}; };
Printf("Duplicata curves", q[]);
Printf("newp=%g", newp);
b[] = Boundary{Curve{q[0]};}; Printf("boundary of first copy", b[]);
s[] = Duplicata{ Surface{1}; };
Printf("Duplicata surface", s[]);
Printf("newp=%g newl=%g newll=%g", newp, newl, newll);
