// hello.geo: a first stereomesh script, `stereomesh -0 examples/hello.geo`.
// It meshes nothing (docs/tutorial.md makes a mesh): it shows the language, an
// Include from stdlib/, DefineConstant, a macro, lists, loops and Printf. It prints where a few
// coastal cities land in the stereographic plane that PolarSphere uses
// (Gmsh 4.8.4, PolarSphere: u = -x/(r+z), v = -y/(r+z) on a sphere of radius r).
Include "earth.geo";

DefineConstant[ radius = 1 ];   // try -setnumber radius 6371e3

// Input: lon, lat in degrees. Output: x, y, z on the sphere and (u, v).
Macro LonLatToStereo
  x = radius * Cos(lat * Deg2Rad) * Cos(lon * Deg2Rad);
  y = radius * Cos(lat * Deg2Rad) * Sin(lon * Deg2Rad);
  z = radius * Sin(lat * Deg2Rad);
  u = -x / (radius + z);
  v = -y / (radius + z);
Return

names[] = Str("Brest", "Cape Town", "Honolulu", "Reykjavik", "Hobart");
lons[] = {-4.49, 18.42, -157.86, -21.94, 147.33};
lats[] = {48.39, -33.92, 21.31, 64.15, -42.88};

Printf("%g cities, sphere radius %g", #lons[], radius);
north = 0;
For i In {0:#lons[]-1}
  lon = lons[i];
  lat = lats[i];
  Call LonLatToStereo;
  Printf(StrCat(names[i], ": u = %.4f, v = %.4f, |(u,v)| = %.4f"), u, v, Hypot(u, v));
  If (lat > 0)
    north++;
  EndIf
EndFor
// The northern hemisphere maps inside the unit disk (for a unit sphere).
Printf("%g of %g cities are north of the equator", north, #lons[]);
