// Options: defaults, assignment, aliases, arithmetic.
Printf("%g", Mesh.Algorithm);  // expect: 6
Mesh.Algorithm = 5;
Printf("%g", Mesh.Algorithm);  // expect: 5
Printf("%g", Mesh.CharacteristicLengthMax);  // expect: 1e+22
Mesh.CharacteristicLengthMax = 5;
Printf("%g", Mesh.MeshSizeMax);  // expect: 5
Mesh.MeshSizeMin = 0.5;
Printf("%g", Mesh.CharacteristicLengthMin);  // expect: 0.5
Mesh.MeshSizeFactor *= 2;
Printf("%g", Mesh.MeshSizeFactor);  // expect: 2
Printf("%g", Mesh.MshFileVersion);  // expect: 4.1
Printf("%g", General.Verbosity);  // expect: 5
Printf("%g", Geometry.Tolerance);  // expect: 1e-08
Printf("%g", Geometry.OldNewReg);  // expect: 1
Printf("%g", Mesh.NbNodes);  // expect: 0
Mesh.Smoothing++;
Printf("%g", Mesh.Smoothing);  // expect: 2
Mesh.ElementOrder = 2;
Printf("%g", Mesh.ElementOrder);  // expect: 2
Geometry.Color.Points = {1, 2, 3};
Geometry.Color.Curves = Red;
Printf("%g", Mesh.RandomFactor);  // expect: 1e-09
