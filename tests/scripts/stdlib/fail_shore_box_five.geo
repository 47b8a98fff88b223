// ShoreProximity takes ShoreBox[] as a box {W, E, S, N} only: 5 numbers (a box with one too
// many, or the start of a polygon) would drop the wrong points, so it is an error located at
// the macro's check (line 59 of stdlib/ocean_fields.geo).
// compare_with_gmsh: skip (stdlib search path)
Include "ocean_fields.geo";
Call EarthSphere;
p_ = newp;
Point(p_) = {0, 0, 1};
ShorePoints[] = {p_};
ShoreBox[] = {-7, -2.5, 51.5, 55.5, 0};
Call ShoreProximity;
// expect error: 59:9: user-error
