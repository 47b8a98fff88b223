// Figure 5 of Lambrechts et al. (2008), section 2.2: GSHHS full-resolution Great Britain and
// Ireland coarsened with a constant accuracy gamma. Pick it on the command line:
//   stereomesh examples/gb_ireland_coarsening.geo -setnumber gamma 15000
// (gamma in metres: 100000, 15000, 1500 or 150, the paper's four panels). Prints the number
// of islands (holes of the ocean surface) and of their control points, and checks them
// against our reference counts on GSHHG 2.3.7 (docs/coastlines.md section 8, paper's in
// brackets): 100 km 2 / 40 [2], 15 km 16 / 594 [~15], 1.5 km 155 / 10,332 [152],
// 150 m 2,438 / 81,848 [2,176 / 83,277].
DefineConstant[ gamma = 15000, quiet = 0, MeshAtAccuracy = 1 ];
// quiet: no Printf (the script tests include this file); MeshAtAccuracy = 0: no mesh sizes
// (examples/gb_ireland.geo includes this file and sets its own).

R = 6371009;                       // metres: the accuracy field is evaluated on this sphere
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};

Field[1] = MathEval;
Field[1].F = Sprintf("%.17g", gamma);

Coastline[1] = LonLatText;
Coastline[1].FileName = "../data/gshhg/gb_ireland_f.txt";
Coastline[1].AccuracyField = 1;
// The paper's coarsening as it is (its Figure 5 counts the points coarsening keeps): no
// control points put back where the B-spline leaves the data (docs/coastlines.md).
Coastline[1].DeviationFactor = 0;
// No Region: the file's own -R box (-11/2/49/61) closes the cut French coast.

loops[] = Coastline{1};
counts[] = Coastline{1, "ControlPoints"};   // per loop, aligned with loops[]
open[] = Coastline{1, "OpenCurves"};
islands = #loops[] - 1;                      // loops[0] is the ocean's outer loop
points = 0;
For i In {1 : #loops[] - 1}
  points += counts[i];
EndFor
If (!quiet)
  Printf("gamma %g m: %g islands, %g control points (outer loop %g points, %g open-boundary curves)",
         gamma, islands, points, counts[0], #open[]);
EndIf

Plane Surface(1) = loops[];
// Meshed (-2), the coast as coarsened is drawn to gamma: edges of that size follow it (no
// smaller than 5 km, so that the 150 m panel stays near 100,000 triangles). Without a size
// the curves get 150 km chords that cut across their own bays, and the mesh has slivers
// no split on the curve can mend (rho 0).
If (MeshAtAccuracy)
  Mesh.MeshSizeMax = Max(gamma, 5e3);
  Mesh.MeshSizeExtendFromBoundary = 0;
EndIf

// Reference counts (GSHHG 2.3.7) with the tolerances tests/scripts/coastline/figure5_*.geo check.
ref_islands = 0;  ref_points = 0;
If (gamma == 100000)
  ref_islands = 2;  ref_points = 40;
ElseIf (gamma == 15000)
  ref_islands = 16;  ref_points = 594;
ElseIf (gamma == 1500)
  ref_islands = 155;  ref_points = 10332;
ElseIf (gamma == 150)
  ref_islands = 2438;  ref_points = 81848;
EndIf
If (ref_islands > 0)
  Assert(Fabs(islands - ref_islands) <= 0.05 * ref_islands, "island count far from the reference");
  Assert(Fabs(points - ref_points) <= 0.05 * ref_points, "control point count far from the reference");
EndIf
Assert(#open[] == 2, "the cut French coast is closed by two open-boundary curves");
