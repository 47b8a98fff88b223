// Extrude's first braces need {dx,dy,dz}, {{axis},{point},angle} or
// {{dx,dy,dz},{axis},{point},angle}: two numbers are an error at the Extrude.
Point(1) = {0, 0, 0, 0.1};
out[] = Extrude {1, 2} { Point{1}; };
// expect error: 4:9: list-size-mismatch
