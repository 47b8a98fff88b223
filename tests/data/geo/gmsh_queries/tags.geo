Point(1)={0,0,0}; Point(2)={1,0,0}; Point(3)={1,1,0}; Point(20)={0,1,0};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,20};
Printf("A newp=%g newl=%g newreg=%g newll=%g news=%g", newp, newl, newreg, newll, news);
Delete{ Point{20}; }
Printf("B newp=%g (point 20 used by line 3)", newp);
Delete{ Line{3}; }
Delete{ Point{20}; }
Printf("C newp=%g newl=%g newreg=%g", newp, newl, newreg);
Physical Point(40) = {1};
Printf("D newreg=%g newp=%g", newreg, newp);
Physical Curve("a") = {1};
Printf("E newreg=%g", newreg);
x[] = Physical Curve{41};
Geometry.OldNewReg = 0;
Printf("F newp=%g newl=%g newreg=%g newll=%g news=%g", newp, newl, newreg, newll, news);
Curve Loop(70) = {1,2};
Printf("G newl=%g newreg=%g newll=%g", newl, newreg, newll);
p[] = Point{2};
Printf("P", p[]);
b[] = Boundary{ Curve{1}; };
Printf("B", b[]);
b[] = Boundary{ Curve{-1}; };
Printf("Bn", b[]);
c[] = Curve{:};
Printf("C", c[]);
q[] = Translate{1,0,0}{ Duplicata{ Point{1}; Curve{2}; } };
Printf("T", q[]);
Printf("H newp=%g newl=%g", newp, newl);
SetMaxTag Point(100);
Printf("I newp=%g", newp);
