// examples/gulf_of_mexico.geo (RegionalSea: the Panama Canal closed, the Gulf's sea kept):
// one sea, no coast point left on the Pacific side of the isthmus (the Gulf of Panama came
// into the mesh through the canal before MinChannelWidth), open boundaries on the East and
// North sides only (the Atlantic), then meshed in 2D.
// compare_with_gmsh: skip (native Coastline and Field statements)
Quiet = 1;
Include "../../../examples/gulf_of_mexico.geo";
Printf("%g sea(s); open curves W %g, E %g, S %g, N %g", #RegionalSurfaces[],
       #Coastline{1, "OpenCurves", "West"}, #Coastline{1, "OpenCurves", "East"},
       #Coastline{1, "OpenCurves", "South"}, #Coastline{1, "OpenCurves", "North"});
// expect: 1 sea(s); open curves W 0, E 4, S 0, N 1
pacific = 0;
pts[] = Coastline{1, "Points"};
For i In {0 : #pts[] - 1}
  p[] = Point{pts[i]};
  lon = Atan2(p[1], p[0]) * 180 / Pi;
  lat = Atan2(p[2], Hypot(p[0], p[1])) * 180 / Pi;
  pacific += lon > -80.5 && lon < -78 && lat < 8.8;
EndFor
Printf("%g coast points in the Gulf of Panama", pacific);
// expect: 0 coast points in the Gulf of Panama
Mesh 2;
Printf("triangles within 10%% of 16478: %g", Fabs(Mesh.NbTriangles - 16478) < 0.1 * 16478);
// expect: triangles within 10% of 16478: 1
// Mesh.QualityFloor (0.3 by default): no triangle below it on this real coast.
Printf("rho min >= 0.3: %g", Mesh.StatsRhoMin >= 0.3);
// expect: rho min >= 0.3: 1
