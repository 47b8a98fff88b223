// TextAttributes packs a View text's style into one number:
// (align << 16) | (font << 8) | size, checked against gmsh 4.8.4.
Printf("%g", TextAttributes("Font", "Helvetica"));  // expect: 1039
Printf("%g", TextAttributes("Font", "Times-Roman"));  // expect: 15
Printf("%g", TextAttributes("Font", "Screen"));  // expect: 3599
Printf("%g", TextAttributes("FontSize", "12"));  // expect: 12
Printf("%g", TextAttributes("FontSize", "12.7"));  // expect: 12
Printf("%g", TextAttributes("FontSize", " 9pt"));  // expect: 9
Printf("%g", TextAttributes("FontSize", ""));  // expect: 0
Printf("%g", TextAttributes("Align", "Center"));  // expect: 65551
Printf("%g", TextAttributes("Align", "left"));  // expect: 15
Printf("%g", TextAttributes("Align", "right"));  // expect: 131087
Printf("%g", TextAttributes("Align", "TopRight"));  // expect: 327695
Printf("%g", TextAttributes("Align", "CenterRight"));  // expect: 524303
Printf("%g", TextAttributes("Font", "Courier-Bold", "FontSize", "20", "Align", "TopLeft"));  // expect: 198932
Printf("%g", TextAttributes("Font", "Helvetica", "Font", "Courier"));  // expect: 2063
Printf("%g", TextAttributes("Font", "Courier", "FontSize", "-3"));  // expect: -3
Printf("%g", TextAttributes("Font", "Courier", "FontSize", "300"));  // expect: 2348
S[] = Str("Font", "Symbol", "Align", "BottomRight");
Printf("%g", TextAttributes(S()));  // expect: 134159
General.FontSize = 20;
Printf("%g", TextAttributes("Align", "CenterCenter"));  // expect: 458767
