// The Gulf of Mexico with the western Caribbean (box 98W-76W, 7N-31N): the Panama Canal and
// the narrow passages of the Florida and Cuban keys closed by MinChannelWidth = 2 km, the
// Gulf's sea kept by SeaAt, so the Pacific south of the isthmus stays out (docs/coastlines.md).
//   stereomesh -2 examples/gulf_of_mexico.geo -o gulf.14
DefineConstant[ ShoreSizeMin = 10e3, ShoreSizeMax = 60e3, ShoreDistMax = 300e3, RegionalAccuracy = 5e3,
                RegionalMinChannelWidth = 2e3 ];
Include "regions.geo";
Include "ocean_fields.geo";
Call EarthSphere;
RegionalResolution = "i";   // GSHHG intermediate from the system (gmt-gshhg-high)
RegionalMinArea = 100;      // km^2
RegionalBox[] = {RegionGulfOfMexico[]};
RegionalSeaAt[] = {CentralGulfOfMexico[]};
Call RegionalSea;
ShorePoints[] = RegionalShorePoints[];  ShoreBox[] = RegionalBox[];
Call ShoreProximity;
OceanFields[] = {ShoreField};
Call OceanSize;
// ETOPO5 depths at the nodes of the fort.14 / hgrid.gr3 / UGRID file (5 m at least: the
// shallowest water a wetting-free run takes), and the Courant time step in the summary.
GulfDepth = newf;
Field[GulfDepth] = Bathymetry;
Field[GulfDepth].FileName = StrCat(BathyDir, "etopo5_global_0.25deg.nc");
Field[GulfDepth].Output = "depth";
Field[GulfDepth].MinDepth = 5;
Mesh.DepthField = GulfDepth;
