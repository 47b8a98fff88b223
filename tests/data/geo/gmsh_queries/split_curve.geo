For i In {1:6}
Point(i)={Cos(i),Sin(i),0};
EndFor
BSpline(1)={1:6,1};
Line(2)={1:6};
s[]=Split Curve{1} Point{3,5};
Printf("split periodic", s[]);
t[]=Split Curve{2} Point{2,4};
Printf("split line", t[]);
Printf("newl %g", newl);
