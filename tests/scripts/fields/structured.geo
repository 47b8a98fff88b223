// Structured (Gmsh's text grid: z fastest, then y, then x) on the ETOPO5 GBR
// grid, the same nodes as bathymetry.geo: z(150E, 15S) = -1856,
// z(150.0833E, 15S) = -1776, z(140E, 26S) = 75; x = lon, y = lat in degrees.
Field[1] = Structured;
Field[1].FileName = "../../../data/bathymetry/etopo5_gbr_5min.gmsh_structured.txt";
Field[1].TextFormat = 1;
Printf("%.6g", FieldValue(1, 150, -15, 0));          // expect: -1856
Printf("%.6g", FieldValue(1, 150 + 1/24, -15, 0));   // expect: -1816
Printf("%.6g", FieldValue(1, 140, -26, 0));          // expect: 75
// Outside the grid the edge values extend, unless SetOutsideValue.
Printf("%.6g", FieldValue(1, 139, -26, 0));          // expect: 75
Field[1].SetOutsideValue = 1;
Field[1].OutsideValue = 1e22;
Printf("%g", FieldValue(1, 139, -26, 0));            // expect: 1e+22
Field[1].SetOutsideValue = 0;
// On the unit sphere: LonLat gives radians, Param turns them into degrees.
Field[2] = Param;
Field[2].InField = 1;
Field[2].FX = "x * 180 / Pi";
Field[2].FY = "y * 180 / Pi";
Field[3] = LonLat;
Field[3].InField = 2;
Field[3].RadiusStereo = 1;
lon = 150 * Pi / 180;  lat = -15 * Pi / 180;
Printf("%.6g", FieldValue(3, Cos(lat) * Cos(lon), Cos(lat) * Sin(lon), Sin(lat)));   // expect: -1856
