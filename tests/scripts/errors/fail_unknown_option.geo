Mesh.Algoritm = 6;
// expect error: 1:1: unknown-option
