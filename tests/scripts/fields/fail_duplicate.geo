// Gmsh 4.8.4 keeps the first definition and reports "Field id 1 is already defined".
Field[1] = Box;
Field[1] = Ball;
// expect error: 3:7: duplicate-field-id
