Point(1)={0,0,0}; Point(2)={1,0,0}; Point(3)={1,1,0}; 
Line(1)={1,2}; Line(2)={2,3};
q[] = Translate{1,0,0}{ Duplicata{ Point{1}; Curve{2}; } };
Printf("T", q[]);
p[] = Point{:}; Printf("pts", p[]);
c[] = Curve{:}; Printf("curves", c[]);
b[] = Boundary{Curve{3};}; Printf("bnd3", b[]);
Point(10)={5,5,5}; Point(11)={5,5,5};
Delete{Point{11};}
Printf("newp after deleting max %g", newp);
Point(12)={5,5,5};
Delete{Point{10};}
Printf("newp after deleting non-max %g", newp);
Coherence;
p[] = Point{:}; Printf("pts", p[]);
Printf("newp after coherence %g", newp);
r[] = Rotate{{0,0,1},{0,0,0},Pi/2}{ Point{3}; };
Printf("R", r[]);
Printf("p3 %g %g %g", Point{3});
s[] = Symmetry{1,0,0,0}{ Duplicata{Curve{1};} };
Printf("S", s[]);
c[] = Curve{:}; Printf("curves", c[]);
d[] = Dilate{{0,0,0},2}{ Duplicata{Point{2};} };
Printf("D", d[]);
Printf("pd %g %g %g", Point{d[0]});
