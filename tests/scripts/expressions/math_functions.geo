// Math builtins (parentheses and brackets both call a function).
Printf("%g", Sqrt(2));  // expect: 1.41421
Printf("%g", Sqrt[16]);  // expect: 4
Printf("%g", Exp(1));  // expect: 2.71828
Printf("%g", Log(2));  // expect: 0.693147
Printf("%g", Log10(1000));  // expect: 3
Printf("%g", Sin(Pi/2));  // expect: 1
Printf("%g", Cos(0));  // expect: 1
Printf("%g", Tan(Pi/4));  // expect: 1
Printf("%g", Asin(1));  // expect: 1.5708
Printf("%g", ArcSin(1));  // expect: 1.5708
Printf("%g", Acos(0));  // expect: 1.5708
Printf("%g", ArcCos(1));  // expect: 0
Printf("%g", Atan(1));  // expect: 0.785398
Printf("%g", ArcTan(1));  // expect: 0.785398
Printf("%g", Atan2(1, 1));  // expect: 0.785398
Printf("%g", ArcTan2(-1, -1));  // expect: -2.35619
Printf("%g", Sinh(1));  // expect: 1.1752
Printf("%g", Cosh(1));  // expect: 1.54308
Printf("%g", Tanh(1));  // expect: 0.761594
Printf("%g", Fabs(-2.5));  // expect: 2.5
Printf("%g", Abs(-3));  // expect: 3
Printf("%g", Floor(-1.5));  // expect: -2
Printf("%g", Ceil(-1.5));  // expect: -1
Printf("%g", Round(2.5));  // expect: 3
Printf("%g", Round(-2.5));  // expect: -2
Printf("%g", Round(2.4));  // expect: 2
Printf("%g", Fmod(-7, 3));  // expect: -1
Printf("%g", Modulo(7.5, 2));  // expect: 1.5
Printf("%g", Hypot(3, 4));  // expect: 5
Printf("%g", Min(3, 4));  // expect: 3
Printf("%g", Max(3, 4));  // expect: 4
Printf("%g", Rand(0));  // expect: 0
Printf("%.15g", Pi);  // expect: 3.14159265358979
Printf("%g", GMSH_MAJOR_VERSION);  // expect: 4
Printf("%g", GMSH_MINOR_VERSION);  // expect: 8
Printf("%g", GMSH_PATCH_VERSION);  // expect: 4
Printf("%g", MPI_Size);  // expect: 1
Printf("%g", MPI_Rank);  // expect: 0
