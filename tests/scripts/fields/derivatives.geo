// Finite-difference kinds on MathEval inputs whose derivatives are known:
// central differences are exact on quadratics.
Field[1] = MathEval;
Field[1].F = "x^2 + 3*y";
Field[2] = Gradient;
Field[2].InField = 1;  Field[2].Delta = 0.01;  Field[2].Kind = 0;
Printf("%.6g", FieldValue(2, 1, 0, 0));   // expect: 2
Field[2].Kind = 1;
Printf("%.6g", FieldValue(2, 1, 0, 0));   // expect: 3
Field[2].Kind = 3;
Printf("%.6g", FieldValue(2, 1, 0, 0));   // expect: 3.60555
Field[3] = MathEval;
Field[3].F = "x^2 + y^2 + z^2";
Field[4] = Laplacian;
Field[4].InField = 3;  Field[4].Delta = 0.1;
Printf("%.6g", FieldValue(4, 0.3, 0.2, 0.1));   // expect: 6
// Mean: (f(x) + the six neighbours at +-Delta) / 7 = (1.21 + 0.81 + 4 + 1)/7 for x^2 at x = 1.
Field[5] = MathEval;
Field[5].F = "x^2";
Field[6] = Mean;
Field[6].InField = 5;  Field[6].Delta = 0.1;
Printf("%.6g", FieldValue(6, 1, 0, 0));   // expect: 1.00286
// MaxEigenHessian of x^2 + 3 y^2: Hessian diag(2, 6, 0).
Field[7] = MathEval;
Field[7].F = "x^2 + 3*y^2";
Field[8] = MaxEigenHessian;
Field[8].InField = 7;  Field[8].Delta = 0.01;
Printf("%.4g", FieldValue(8, 0.5, 0.5, 0));   // expect: 6
// Curvature of the level sets of sqrt(x^2 + y^2) (circles): 1/r.
Field[9] = MathEval;
Field[9].F = "sqrt(x^2 + y^2)";
Field[10] = Curvature;
Field[10].InField = 9;  Field[10].Delta = 1e-3;
c = FieldValue(10, 2, 0, 0);
Assert(Fabs(c - 0.5) < 1e-4, "curvature %g, expected 0.5", c);
