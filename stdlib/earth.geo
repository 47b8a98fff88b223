// Earth set-up for ocean scripts (Lambrechts et al. 2008, sections 2-3): radius, unit
// conversions, where the data live, the PolarSphere and lon/lat -> 3D macros.
// Found through the Include search path: `Include "earth.geo";`.
//
// Every value is a DefineConstant, so a script (or -setnumber/-setstring) may choose another
// one before the Include. Lengths are in metres: with the sphere of radius EarthRadius that
// `Call EarthSphere;` builds, coastline accuracies, field sizes and Distance fields are all
// in metres.
//
// Included twice (e.g. by a script and by another stdlib file), the second Include does
// nothing: macros cannot be redefined.
If (!Exists(EarthGeoLoaded))
  EarthGeoLoaded = 1;
  DefineConstant[ EarthRadius = 6371e3 ];   // mean Earth radius (m), as in Lambrechts et al. 2008
  Deg2Rad = Pi / 180;
  Rad2Deg = 180 / Pi;
  Km = 1000;                                 // metres per kilometre: 30 * Km
  Nm = 1852;                                 // metres per nautical mile

  // DataDir: the data the project ships (ETOPO5 relief, small GSHHG exports: data/ of the
  // repository, data/PROVENANCE.md), with a trailing slash. It sits beside this stdlib in
  // the source tree, the build tree and an installed prefix (share/stereomesh/{stdlib,data}),
  // so the default is resolved from this file's own directory, whatever the working
  // directory or the script's place. Another data folder: `-setstring DataDir /path/ x.geo`.
  // The full shoreline database comes from the system instead: `Coastline[n] = GSHHG;`.
  DefineConstant[ DataDir = StrCat(CurrentDirectory, "../data/") ];
  GshhgDir = StrCat(DataDir, "gshhg/");
  BathyDir = StrCat(DataDir, "bathymetry/");

  // EarthSphere: makes the Earth the current geometry. Creates the centre and north-pole
  // points and PolarSphere(EarthSphereTag) of radius EarthRadius (stereographic projection
  // from the South Pole, the paper's choice for the World Ocean). Output: EarthSphereTag.
  Macro EarthSphere
    earth_c_ = newp;
    Point(earth_c_) = {0, 0, 0};
    earth_p_ = newp;
    Point(earth_p_) = {0, 0, EarthRadius};
    EarthSphereTag = news;
    PolarSphere(EarthSphereTag) = {earth_c_, earth_p_};
  Return

  // LonLatToXYZ: input lon, lat (degrees); output x, y, z on the sphere of radius EarthRadius,
  // the coordinates FieldValue takes.
  Macro LonLatToXYZ
    x = EarthRadius * Cos(lat * Deg2Rad) * Cos(lon * Deg2Rad);
    y = EarthRadius * Cos(lat * Deg2Rad) * Sin(lon * Deg2Rad);
    z = EarthRadius * Sin(lat * Deg2Rad);
  Return

  // XYZToLonLat: input x, y, z; output lon (-180..180], lat (degrees).
  Macro XYZToLonLat
    lon = Atan2(y, x) * Rad2Deg;
    lat = Atan2(z, Hypot(x, y)) * Rad2Deg;
  Return

  // LonLatPoint: input lon, lat; creates a model point there on the sphere (for Distance
  // fields, e.g. a river mouth) and returns its tag in LonLatPointTag. Needs EarthSphere.
  Macro LonLatPoint
    Call LonLatToXYZ;
    Euclidean Coordinates;
    LonLatPointTag = newp;
    Point(LonLatPointTag) = {x, y, z};
    Coordinates Surface EarthSphereTag;
  Return

  // GreatCircle: input lon1, lat1, lon2, lat2 (degrees); output GreatCircleDistance (m) on the
  // sphere of radius EarthRadius (haversine formula).
  Macro GreatCircle
    gc_a_ = Sin((lat2 - lat1) * Deg2Rad / 2)^2 +
            Cos(lat1 * Deg2Rad) * Cos(lat2 * Deg2Rad) * Sin((lon2 - lon1) * Deg2Rad / 2)^2;
    GreatCircleDistance = 2 * EarthRadius * Asin(Sqrt(Min(1, gc_a_)));
  Return
EndIf
