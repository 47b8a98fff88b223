// ChannelWidth needs at least one element across: the error points at the assignment.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Field[1] = ChannelWidth;
Field[1].CurvesList = {1};
Field[1].ElementsAcross = 0.5;
h = FieldValue(1, 0, 0.5, 0);
// expect error: 7:1: bad-field-value
