Point(1)={0,0,0}; Point(2)={1,0,0}; Point(3)={1,1,0}; Point(4)={0,1,0};
Line(1)={1,2,3}; Line(2)={3,4,1};
Curve Loop(1)={1,2};
Plane Surface(1)={1};
Physical Curve(7)={1};
Split Curve{1} Point{2};
c[]=Curve{:}; Printf("curves", c[]);
b[]=Boundary{Surface{1};}; Printf("bnd", b[]);
p[]=Physical Curve{7}; Printf("phys", p[]);
