// ChannelWidth: the local width of the water / ElementsAcross, clamped to [SizeMin,
// SizeMax]. A canal 10 x 1 as one curve loop (the banks are one ring: facing samples
// are far apart along it), then two square islands 0.1 degrees apart on the sphere
// (tests/data/field/strait_loops2.txt) through CoastlineId.
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {10, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Field[1] = ChannelWidth;
Field[1].CurvesList = {1:4};
Field[1].SizeMax = 10;
Printf("%g", FieldValue(1, 5, 0.5, 0));       // expect: 0.5
Printf("%g", FieldValue(1, 5, 0.1, 0));       // expect: 0.5
Field[1].ElementsAcross = 4;
Printf("%g", FieldValue(1, 5, 0.5, 0));       // expect: 0.25
Field[1].SizeMin = 0.3;
Printf("%g", FieldValue(1, 5, 0.5, 0));       // expect: 0.3
// Outside the canal no coast faces the point within ElementsAcross * SizeMax: SizeMax.
Printf("%g", FieldValue(1, 5, -3, 0));        // expect: 10
Field[1].SizeMax = 0.2;
Field[1].SizeMin = 0;
Printf("%g", FieldValue(1, 5, 0.5, 0));       // expect: 0.2
// One bank alone is not a channel.
Field[2] = ChannelWidth;
Field[2].CurvesList = {1};
Field[2].SizeMax = 10;
Printf("%g", FieldValue(2, 5, 0.5, 0));       // expect: 10

R = 6371e3;
Point(10) = {0, 0, 0};
Point(11) = {0, 0, R};
PolarSphere(1) = {10, 11};
Field[3] = MathEval;
Field[3].F = "2000";
Coastline[1] = Loops2;
Coastline[1].FileName = "../../data/field/strait_loops2.txt";
Coastline[1].AccuracyField = 3;
Coastline[1].CurveType = "Line";
islands[] = Coastline{1};
Field[4] = ChannelWidth;
Field[4].CoastlineId = 1;
Field[4].SizeMax = 50e3;
// The strait at lat 0.25: chord R * 0.1 degrees * cos(0.25 degrees) = 11119 m, over 2.
lon = 0.55 * Pi / 180;  lat = 0.25 * Pi / 180;
h = FieldValue(4, R * Cos(lat) * Cos(lon), R * Cos(lat) * Sin(lon), R * Sin(lat));
Printf("strait %.4g m", h);                   // expect: strait 5560 m
// West of the western island nothing faces the water within 100 km.
lon = -0.2 * Pi / 180;
h = FieldValue(4, R * Cos(lat) * Cos(lon), R * Cos(lat) * Sin(lon), R * Sin(lat));
Printf("open water %g m", h);                 // expect: open water 50000 m
