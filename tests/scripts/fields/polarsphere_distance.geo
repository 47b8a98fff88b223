// Distance on a unit PolarSphere: a line drawn in the stereographic (u,v)
// plane is sampled on the sphere, so every sample is at distance 1 from the
// centre, and the chord distance to a sample is the 3D one.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
// (u,v) = -(x, y)/(1 + z): lon 0 and lon 90 on the equator.
Point(3) = {-1, 0, 0};
Point(4) = {0, -1, 0};
Line(1) = {3, 4};
Field[1] = Distance;
Field[1].CurvesList = {1};
Field[1].NumPointsPerCurve = 3;     // one sample, the (u,v) midpoint (-1/2, -1/2)
Printf("%.6f", FieldValue(1, 0, 0, 0));   // expect: 1.000000
// (u,v) = (-1/2, -1/2) is x = y = 2(1/2)/(1 + 1/2) = 2/3, z = (1 - 1/2)/(1 + 1/2) = 1/3.
Printf("%.6f", FieldValue(1, 2/3, 2/3, 1/3));   // expect: 0.000000
// The points of a geometry are on the sphere too.
Field[2] = Distance;
Field[2].PointsList = {4};
Printf("%.6f", FieldValue(2, 0, 1, 0));   // expect: 0.000000
