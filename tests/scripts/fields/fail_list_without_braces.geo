// Gmsh 4.8.4 ignores a list option given without braces: we warn (and
// ignore it too). An option on an undefined field is an error.
Field[1] = Distance;
Field[1].CurvesList = 3;
Field[2].PointsList = {1};
// expect warning: 4:23: field-list-without-braces
// expect error: 5:7: missing-field
