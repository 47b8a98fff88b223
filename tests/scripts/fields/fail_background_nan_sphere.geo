// On the sphere: a field that is NaN south of the equator (the square root of a negative
// z) is a located error naming the field and the lon/lat of the first bad point.
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
n = 40;
For i In {0:n - 1}
  a = 2 * Pi * i / n;
  lon = 30 * Cos(a) * Pi / 180;
  lat = 30 * Sin(a) * Pi / 180;
  x = Cos(lat) * Cos(lon); y = Cos(lat) * Sin(lon); z = Sin(lat);
  Point(10 + i) = {-x / (1 + z), -y / (1 + z), 0};
EndFor
BSpline(1) = {10 : 10 + n - 1, 10};
Field[7] = MathEval;
Field[7].F = "0.05 * Sqrt(z)";
Background Field = 7;
Mesh.MeshSizeFromPoints = 0;
Mesh 1;
// expect error: 15:1: bad-field-value
