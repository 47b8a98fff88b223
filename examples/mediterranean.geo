// The Mediterranean from Gibraltar (5.6W): Suez Canal, Bosporus and Dardanelles closed by
// MinChannelWidth = 2 km (Gibraltar, 14 km, stays open), the central sea kept by SeaAt,
// the open boundary at Gibraltar only (docs/coastlines.md). stereomesh -2 examples/mediterranean.geo -o med.14
DefineConstant[ ShoreSizeMin = 10e3, ShoreSizeMax = 60e3, ShoreDistMax = 300e3, RegionalAccuracy = 5e3,
                RegionalMinChannelWidth = 2e3 ];
Include "regions.geo";
Include "ocean_fields.geo";
Call EarthSphere;
RegionalResolution = "i";   // GSHHG intermediate from the system (gmt-gshhg-high)
RegionalMinArea = 100;      // km^2
RegionalBox[] = {RegionMediterranean[]};
RegionalSeaAt[] = {CentralMediterranean[]};
Call RegionalSea;
ShorePoints[] = RegionalShorePoints[];  ShoreBox[] = RegionalBox[];
Call ShoreProximity;  OceanFields[] = {ShoreField};  Call OceanSize;
