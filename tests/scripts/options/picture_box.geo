// Mesh.PictureBox (native): {W, E, S, N} in degrees, all 0 for none (the whole mesh);
// W > E is a box across the dateline. Mesh.PictureWorst and the new colourings.
b[] = Mesh.PictureBox;
Printf("%g %g", #b[], b[1]);   // expect: 4 0
Mesh.PictureBox = {170, -170, 50, 66};
b[] = Mesh.PictureBox;
Printf("%g %g %g %g", b[0], b[1], b[2], b[3]);   // expect: 170 -170 50 66
Mesh.PictureBox = {-6.5, -4.5, 35.5, 36.5};
c[] = Mesh.PictureBox;
Printf("%g", c[1]);   // expect: -4.5
Mesh.PictureBox = {0, 0, 0, 0};
Printf("%g", Mesh.PictureWorst);   // expect: 10
Mesh.PictureWorst = 0;
Mesh.PictureColour = 3;
Printf("%g %g", Mesh.PictureColour, Mesh.PictureWorst);   // expect: 3 0
// compare_with_gmsh: skip (native options)
