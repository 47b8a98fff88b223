// RegionalSea takes the coastline's gamma as a size field (RegionalAccuracyField) instead
// of a constant: 2 km west of 4.5W and 5 km east of it gives fewer control points than 2 km
// everywhere and more than 5 km everywhere (the same coast imported by hand with each
// constant), and RegionalAccuracyField still names the field given.
// compare_with_gmsh: skip (native Coastline statements)
Include "earth.geo";
Include "regions.geo";
Call EarthSphere;
RegionalFile = StrCat(GshhgDir, "gb_ireland_f.txt");
RegionalBox[] = {-7, -2.5, 51.5, 55.5};
RegionalSeaAt[] = {-5.4, 53.35};
east_coarse_ = newf;
Field[east_coarse_] = MathEval;
// Longitude > 4.5W is y > -tan(4.5 deg) x where x > 0 (as in the whole box).
Field[east_coarse_].F = "2e3 + 3e3 * step(y + 0.0787017068 * x)";
RegionalAccuracyField = east_coarse_;
Call RegionalSea;
field_points_ = #RegionalShorePoints[];

For k In {0 : 1}
  gamma_[k] = newf;
  Field[gamma_[k]] = MathEval;
  Field[gamma_[k]].F = Sprintf("%g", k == 0 ? 2e3 : 5e3);
  Coastline[2 + k] = LonLatText;
  Coastline[2 + k].FileName = RegionalFile;
  Coastline[2 + k].AccuracyField = gamma_[k];
  Coastline[2 + k].Region = {RegionalBox[]};
  Coastline[2 + k].SeaAt = {RegionalSeaAt[]};
  constant_points_[k] = #Coastline{2 + k, "Points"};
EndFor
Printf("%g %g %g", field_points_ < constant_points_[0], field_points_ > constant_points_[1],
       RegionalAccuracyField == east_coarse_);
// expect: 1 1 1
