// Periodic Surface with a transform, read back by Gmsh (periodic_surface_readers.py): from
// surface 1 (a square with an embedded point and an embedded curve), surface 2 by
// Translate, surface 3 by Rotate (a quarter turn about z through (-0.25, -0.25, 0)), surface 4 by
// Affine (mirrored in y = -1.5), and surface 5 a copy of surface 2 (a chain, by Translate).
Point(1) = {0, 0, 0, 0.08}; Point(2) = {1, 0, 0, 0.04}; Point(3) = {1, 1, 0, 0.08}; Point(4) = {0, 1, 0, 0.08};
Point(5) = {0.3, 0.3, 0, 0.02}; Point(6) = {0.5, 0.7, 0, 0.03}; Point(7) = {0.8, 0.5, 0, 0.03};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1}; Line(5) = {6, 7};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point{5} In Surface{1}; Curve{5} In Surface{1};
// The copies' points, curves and embedded entities: surface 1's moved by each map.
maps[] = {};
For k In {2 : 5}
  p = 10 * k;
  For i In {1 : 7}
    x = Point{i}; X = x[0]; Y = x[1];
    If (k == 2) X += 2; EndIf
    If (k == 3) t = X; X = -Y - 0.5; Y = t; EndIf
    If (k == 4) Y = -3 - Y; EndIf
    If (k == 5) X += 4; EndIf
    Point(p + i) = {X, Y, 0, 0.5};
  EndFor
  Line(p + 1) = {p + 1, p + 2}; Line(p + 2) = {p + 2, p + 3}; Line(p + 3) = {p + 3, p + 4};
  Line(p + 4) = {p + 4, p + 1}; Line(p + 5) = {p + 7, p + 6};
  Curve Loop(k) = {p + 1, p + 2, p + 3, p + 4}; Plane Surface(k) = {k};
  Point{p + 5} In Surface{k}; Curve{p + 5} In Surface{k};
EndFor
Periodic Surface {5} = {2} Translate {2, 0, 0};
Periodic Surface {2} = {1} Translate {2, 0, 0};
Periodic Surface {3} = {1} Rotate {{0, 0, 1}, {-0.25, -0.25, 0}, Pi / 2};
Periodic Surface {4} = {1} Affine {1, 0, 0, 0, 0, -1, 0, -3, 0, 0, 1, 0, 0, 0, 0, 1};
Mesh 2;
Save StrCat(OutDir, "/forms.msh");
Mesh.MshFileVersion = 2.2;
Save StrCat(OutDir, "/forms22.msh");
