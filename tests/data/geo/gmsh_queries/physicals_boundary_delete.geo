Point(1)={0,0,0}; Point(2)={1,0,0}; Point(3)={1,1,0}; Point(4)={0,1,0}; Point(5)={2,0,0}; Point(6)={2,1,0};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,1}; Line(5)={2,5}; Line(6)={5,6}; Line(7)={6,3};
Curve Loop(1)={1,2,3,4}; Plane Surface(1)={1};
Curve Loop(2)={5,6,7,-2}; Plane Surface(2)={2};
Physical Curve(5) = {1};
Physical Curve(5) = {2};
x[] = Physical Curve{5}; Printf("phys5", x[]);
Physical Curve(5) += {3};
x[] = Physical Curve{5}; Printf("phys5", x[]);
Physical Curve(5) -= {1};
x[] = Physical Curve{5}; Printf("phys5", x[]);
Physical Curve("coast") = {4};
Physical Surface("sea") = {1,2};
Physical Curve("coast") += {5};
Physical Curve("open", 20) = {6};
Physical Point("p") = {1};
Printf("newreg %g", newreg);
b[] = Boundary{Surface{1};}; Printf("bs1", b[]);
b[] = Boundary{Surface{2};}; Printf("bs2", b[]);
b[] = CombinedBoundary{Surface{1,2};}; Printf("cb", b[]);
b[] = Boundary{Surface{1,2};}; Printf("b12", b[]);
b[] = CombinedBoundary{Curve{1,5};}; Printf("cbc", b[]);
b[] = Boundary{Curve{1,5};}; Printf("bc", b[]);
Delete{Curve{2};}
c[] = Curve{:}; Printf("after delete used curve", c[]);
Recursive Delete{Surface{2};}
c[] = Curve{:}; Printf("after recursive delete", c[]);
p[] = Point{:}; Printf("pts", p[]);
s[] = Surface{:}; Printf("surfs", s[]);
