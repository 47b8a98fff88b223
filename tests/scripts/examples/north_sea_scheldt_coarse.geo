// examples/north_sea_scheldt.geo (Figure 13) at a smaller setting: 2 km in the estuary and
// 20 km on the coasts. The example asserts the sizes at Antwerp, at the mouth, 80 km off it
// and in the central North Sea; this prints the model's figures.
// compare_with_gmsh: skip (native Coastline and Field statements)
EstuarySize = 2000;
CoastSize = 20e3;
Quiet = 1;
Include "../../../examples/north_sea_scheldt.geo";
Printf("%g seas, %g open-boundary curves, %g kept shore points", seas, #open[], #ShorePoints[]);
Printf("Antwerp %.0f m, central North Sea %.0f km", antwerp, offshore / Km);
// expect: 3 seas, 15 open-boundary curves, 366 kept shore points
// expect: Antwerp 2000 m, central North Sea 50 km
