// Periodic Surface whose target runs its boundary clockwise (its loop {8, 7, -6, -5}) where
// the translation takes the source's counter-clockwise boundary onto it counter-clockwise:
// the copy's triangles are reversed, turning as the target's loop does (as surface 2 is
// meshed without the statement). Saved for periodic_surface_readers.py; OutDir is set by it.
DefineConstant[ OutDir = "." ];
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.05}; Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Point(5) = {3, 0, 0, 0.5}; Point(6) = {4, 0, 0, 0.5}; Point(7) = {4, 1, 0, 0.5}; Point(8) = {3, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {8, 7}; Line(8) = {5, 8};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {8, 7, -6, -5}; Plane Surface(2) = {2};
Periodic Surface 2 {5, 6, -7, -8} = 1 {1, 2, 3, 4};
Physical Surface(1) = {1}; Physical Surface(2) = {2};
Mesh 2;
Save StrCat(OutDir, "/flip.msh");
