// Distance to model points and curves: Gmsh samples NumPointsPerCurve = N
// points per curve at t = i/(N-1), i = 1..N-2 (end points excluded), and the
// deprecated names (Attractor, NodesList, EdgesList, NNodesByEdge, Sampling).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 2, 0};
Point(5) = {0, 1, 0};
Line(1) = {1, 2};
Field[1] = Distance;
Field[1].CurvesList = {1};
Field[1].NumPointsPerCurve = 11;          // samples at x = 0.1, ..., 0.9
Printf("%g", FieldValue(1, 0, 0, 0));      // expect: 0.1
Printf("%g", FieldValue(1, 0.5, 0, 0));    // expect: 0
Printf("%.6g", FieldValue(1, 0.55, 0.3, 0));   // expect: 0.304138
Field[1].PointsList = {3};
Printf("%g", FieldValue(1, 0, 1.9, 0));    // expect: 0.1
// Chord distance in 3D.
Printf("%g", FieldValue(1, 0.5, 0, 2));    // expect: 2
// A reversed curve tag samples the same points.
Field[1].CurvesList = {-1};
Printf("%g", FieldValue(1, 0, 0, 0));      // expect: 0.1

Field[2] = Attractor;
Field[2].NodesList = {1};
Printf("%g", FieldValue(2, 3, 4, 0));      // expect: 5
Field[3] = Distance;
Field[3].EdgesList = {1};
Field[3].NNodesByEdge = 3;                 // one sample, at x = 0.5
Printf("%g", FieldValue(3, 0, 0, 0));      // expect: 0.5
Field[3].Sampling = 5;                     // x = 0.25, 0.5, 0.75
Printf("%g", FieldValue(3, 0, 0, 0));      // expect: 0.25

// A quarter circle of radius 1 around Point 1: samples at uniform angles.
Circle(2) = {2, 1, 5};
Field[4] = Distance;
Field[4].CurvesList = {2};
Field[4].NumPointsPerCurve = 3;            // one sample, at 45 degrees
Printf("%.6g", FieldValue(4, Cos(Pi/4), Sin(Pi/4), 0));   // expect: 0
Printf("%.6g", FieldValue(4, 0, 0, 0));    // expect: 1

// Moving a point changes the distance: builds follow the model.
Field[5] = Distance;
Field[5].PointsList = {3};
Printf("%g", FieldValue(5, 0, 0, 0));      // expect: 2
Translate {0, 1, 0} { Point{3}; }
Printf("%g", FieldValue(5, 0, 0, 0));      // expect: 3

// Lists take ranges and entity queries, as in Gmsh.
Field[6] = Distance;
Field[6].CurvesList = {Curve{:}};
Field[6].NumPointsPerCurve = 3;            // the midpoints of Line 1 and Circle 2
Printf("%.6g", FieldValue(6, 0.5, 0, 0));  // expect: 0
Field[6].PointsList = {1:2};
Printf("%g", FieldValue(6, 1, 0, 0));      // expect: 0
