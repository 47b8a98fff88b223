// The coast curve within a bound of the source shoreline (docs/coastlines.md, "The curve
// within a bound of the data"): GSHHG crude at gamma = 100 km, measured only
// (DeviationFactor 0), then held within gamma / 2 (the default), then within 20 km by
// MaxDeviation. At crude
// resolution some spans at sharp corners have no source point left to put back (Timor's
// tip, 95 km), so the bound holds for 95% of the points and the largest distance only drops.
// compare_with_gmsh: skip (native Coastline statements)
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "100e3";
For c In {1 : 3}
  Coastline[c] = GSHHG;
  Coastline[c].Resolution = "c";
  Coastline[c].AccuracyField = 1;
EndFor
Coastline[1].DeviationFactor = 0;
Coastline[3].MaxDeviation = 20e3;
l1[] = Coastline{1};  d1[] = Coastline{1, "Deviation"};
l2[] = Coastline{2};  d2[] = Coastline{2, "Deviation"};
l3[] = Coastline{3};  d3[] = Coastline{3, "Deviation"};
// {max, 95%, max before, lon, lat, points put back}
Printf("measured only: %g values, max over 50 km %g, nothing put back %g", #d1[], d1[0] > 50e3, d1[5] == 0);
Printf("gamma / 2: max lower %g, 95%% within %g, points put back %g, max before as measured %g",
       d2[0] < d1[0], d2[1] <= 50e3, d2[5] > 0, d2[2] == d1[0]);
Printf("MaxDeviation 20 km: 95%% within 40 km %g, more points than gamma / 2 %g", d3[1] <= 40e3, d3[5] > d2[5]);
// expect: measured only: 6 values, max over 50 km 1, nothing put back 1
// expect: gamma / 2: max lower 1, 95% within 1, points put back 1, max before as measured 1
// expect: MaxDeviation 20 km: 95% within 40 km 1, more points than gamma / 2 1
