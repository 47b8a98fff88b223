// A text export with an unreadable point in its second segment: the reader's error names
// the file, the record and the line; nothing is imported.
R = 6371009;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, R};
PolarSphere(1) = {1, 2};
Field[1] = MathEval;
Field[1].F = "10000";
Coastline[1] = LonLatText;
Coastline[1].FileName = "../../data/coast_scripts/bad_record.txt";
Coastline[1].AccuracyField = 1;
loops[] = Coastline{1};
// expect error: 10:1: coastline-error
