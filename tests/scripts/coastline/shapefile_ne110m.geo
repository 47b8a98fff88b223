// Natural Earth 1:110m land polygons (ESRI shapefile through shapelib) at gamma = 300 km on
// a unit PolarSphere whose radius is 1: the accuracy field is then in units of the radius
// (300 km / 6371 km). Antarctica is a land polygon wrapping the South Pole: it is the
// outer loop; the shapefile has no levels (every outer ring is level 1, Antarctica too).
// compare_with_gmsh: skip (native Coastline statements)
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 1};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "300 / 6371";
Coastline[7] = Shapefile;
Coastline[7].FileName = "../../../data/naturalearth/ne_110m_land.shp";
Coastline[7].AccuracyField = 1;
Coastline[7].DeviationFactor = 0;   // the coarsening's control points (no data point put back)
loops[] = Coastline{7};
outer[] = Coastline{7, "Outer"};
n[] = Coastline{7, "ControlPoints"};
pts[] = Coastline{7, "Points"};
Printf("%g outer loop, first returned: %g", #outer[], outer[0] == loops[0]);
p[] = Point{pts[0]};
Printf("outer loop in the south: %g, on the unit sphere: %g", p[2] < -0.8, Fabs(p[0]^2 + p[1]^2 + p[2]^2 - 1) < 1e-12);
Plane Surface(1) = loops[];
// 25 islands, 649 control points with Natural Earth 5.1 (ranges allow kernel tuning).
Printf("islands between 21 and 29: %g", #loops[] - 1 >= 21 && #loops[] - 1 <= 29);
Printf("points between 550 and 750: %g", #pts[] >= 550 && #pts[] <= 750);
// expect: 1 outer loop, first returned: 1
// expect: outer loop in the south: 1, on the unit sphere: 1
// expect: islands between 21 and 29: 1
// expect: points between 550 and 750: 1
