Mesh.Algorithm = 4;
// expect error: 1:18: invalid-option-value
