// Mesh.ElementsAcrossChannels between 0 and 1 is refused before any meshing, at the Mesh
// statement, with a note at the assignment; a negative value where it is set.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Mesh.ElementsAcrossChannels = 0.5;
Mesh 2;                                  // expect error: 12:1: invalid-option-value: Mesh.ElementsAcrossChannels = 0.5: a channel needs at least 1 element across (0 turns the criterion off)
