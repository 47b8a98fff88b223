// stdlib/regions.geo: the paper's boxes and places, and InBox across the dateline.
// compare_with_gmsh: skip (stdlib search path)
Include "regions.geo";
Include "regions.geo";   // a second Include does nothing
Printf("%g %g %g %g", RegionGBR[0], RegionGBR[1], RegionGBR[2], RegionGBR[3]);   // expect: 142 154 -25 -10
Printf("%g", #RegionArctic[]);   // expect: 4
box[] = RegionCanadianArchipelago[];
lon = -95; lat = 74.3; Call InBox; Printf("Barrow Strait %g", InBoxResult);   // expect: Barrow Strait 1
lon = 265; Call InBox; Printf("as 265E %g", InBoxResult);                   // expect: as 265E 1
lon = 25; lat = 71; Call InBox; Printf("Norway %g", InBoxResult);           // expect: Norway 0
lon = -95; lat = 59; Call InBox; Printf("Hudson Bay %g", InBoxResult);      // expect: Hudson Bay 0
// A box across the dateline (the Chatham Islands and New Zealand).
box[] = {160, 200, -50, -30};
lon = -176.5; lat = -44; Call InBox; Printf("Chatham %g", InBoxResult);     // expect: Chatham 1
lon = 150; Call InBox; Printf("Tasmania %g", InBoxResult);                  // expect: Tasmania 0
// Edges count as inside.
box[] = RegionGBIreland[];
lon = -11; lat = 61; Call InBox; Printf("corner %g", InBoxResult);          // expect: corner 1
lon = LizardIsland[0]; lat = LizardIsland[1];
box[] = RegionGBR[]; Call InBox; Printf("Lizard in the GBR box %g", InBoxResult);   // expect: Lizard in the GBR box 1
box[] = RegionNorthSeaScheldt[];
lon = Antwerp[0]; lat = Antwerp[1]; Call InBox; Printf("Antwerp %g", InBoxResult);   // expect: Antwerp 1
