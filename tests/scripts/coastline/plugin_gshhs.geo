// Gmsh 2.6's Plugin(GSHHS) with its old options: gshhs_c.b coarsened at 500 km, written as
// the plugin's .geo (PolarSphere, points, BSplines, Line Loops, and the Plane Surface Gmsh
// 2.6 forgot), then included back. The output goes to $TMPDIR (or /tmp) unless
// `-setstring out FILE` names it; plugin_gshhs_gmsh.sh also loads it in Gmsh 4.8.4.
// compare_with_gmsh: skip (Plugin(GSHHS) does not exist in Gmsh 4.8.4)
If (!Exists(out))
  out = StrCat(StrLen(GetEnv("TMPDIR")) ? GetEnv("TMPDIR") : "/tmp", "/stereomesh_plugin_gshhs_test.geo");
EndIf
Field[1] = MathEval;
Field[1].F = "500e3";
Plugin(GSHHS).InFileName = "../../../data/gshhs/gshhs_c.b";
Plugin(GSHHS).OutFileName = out;
Plugin(GSHHS).iField = 1;
Plugin(GSHHS).Format = "gshhs";
Plugin(GSHHS).radius = 6371009;
Plugin(GSHHS).WritePolarSphere = 1;
Plugin(GSHHS).MinStraitsFactor = 0;
Plugin(GSHHS).Run;
Include out;
s[] = Surface{:};
c[] = Curve{:};
b[] = Boundary{ Surface{s[0]}; };
Printf("%g surface bounded by every curve: %g", #s[], #b[] == #c[]);
// Antarctica's loop is the outer one: its first point is in the south (z < -R sin 60).
x[] = Point{IP + 2};
Printf("outer loop in the south: %g", x[2] < -6371009 * Sin(60 * Pi / 180));
Printf("islands between 5 and 20: %g", #c[] - 1 >= 5 && #c[] - 1 <= 20);
// 13 islands with GSHHG 2.3 crude at 500 km (14 curves).
// expect: 1 surface bounded by every curve: 1
// expect: outer loop in the south: 1
// expect: islands between 5 and 20: 1
