// A shoreline file that does not exist: reported at the FileName statement (the import that
// read it comes as a note) with the reader's message naming the file.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "no_such_coast.txt";
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
// expect error: 10:1: coastline-error
