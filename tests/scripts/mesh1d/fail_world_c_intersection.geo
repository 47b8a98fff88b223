// The GSHHG crude coastlines of world_c.txt as the boundary of one surface: the closed
// B-spline of a 3-point island off north-east Borneo (curve 583) crosses Borneo's (curve
// 12) near 118.33 E, 4.66 N (checked independently by sampling both splines densely).
// The paper's repair splits the crossing edges until they are shorter than the geometric
// tolerance, then stops with the located error (Gmsh 4.8.4 -1 does not check this).
Include "../../data/geo_scripts/world_c.geo";
Field[1] = MathEval;
Field[1].F = "0.004 + 0.02 * Fabs(z)";
Background Field = 1;
Mesh.MeshSizeFromPoints = 0;
Mesh 1;   // expect error: 11:1: curves-intersect
// compare_with_gmsh: skip
