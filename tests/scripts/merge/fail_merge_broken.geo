// A merged mesh file whose element uses a node it does not define is refused at the
// file's name, with the file's line (broken.msh, line 10).
Merge "broken.msh";   // expect error: 3:7: cannot-open-file
