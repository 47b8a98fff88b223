// The paper's mesh size criteria (Lambrechts et al. 2008, section 3.1) as macros driven by
// variables: shore proximity, gravity-wave wavelength from the bathymetry (f1) and the
// bathymetry Hessian (f2), each clamped by a Threshold, combined by a Min.
//
//   Include "earth.geo";  Include "ocean_fields.geo";
//   Call EarthSphere;  ...  loops[] = Coastline{1};
//   ShorePoints[] = Coastline{1, "Points"};  Call ShoreProximity;
//   BathyFile = StrCat(BathyDir, "etopo5_global_0.25deg.nc");
//   Call WaveLength;  Call BathyHessian;
//   OceanFields[] = {ShoreField, WaveField, HessianField};  Call OceanSize;
//
// Sizes and distances are in metres on the sphere of earth.geo's EarthSphere. The defaults
// are the paper's World Ocean (Figures 9-10); set a variable before the Call to change it.
// Each macro takes new field ids (newf), so they can be called more than once (e.g. two
// shore criteria with different coasts); the output variables name the fields made last.
//
// Included twice (e.g. by a script and by another stdlib file), the second Include does
// nothing: macros cannot be redefined.
If (!Exists(OceanFieldsGeoLoaded))
  OceanFieldsGeoLoaded = 1;
  Include "earth.geo";

  // Shore proximity (the paper's f3 in section 3.1, "f1" in section 4.1): the distance to
  // the coast d, and delta = ShoreSizeMin + alpha(d) (ShoreSizeMax - ShoreSizeMin) with alpha
  // linear from ShoreDistMin to ShoreDistMax. The paper's world: 30-200 km within 500 km.
  DefineConstant[ ShoreSizeMin = 30e3, ShoreSizeMax = 200e3, ShoreDistMin = 0,
                  ShoreDistMax = 500e3, ShoreSamples = 20 ];

  // Wavelength (f1): lambda_min / N sqrt(H_ref / H), clamped to [WaveSizeMin, WaveSizeMax].
  // The paper's world: 25-500 km; lambda_min / N = 25 km where the ocean is 4000 m deep.
  DefineConstant[ WaveLengthMin = 250e3, PointsPerWaveLength = 10, DepthRef = 4000,
                  MinDepth = 10, WaveSizeMin = 25e3, WaveSizeMax = 500e3 ];

  // Bathymetry Hessian (f2): 1 / sqrt(|lambda_max|) of the Hessian of H / H_ref (metres),
  // clamped to [HessianSizeMin, HessianSizeMax]. The paper's world: 25-500 km.
  DefineConstant[ HessianSizeMin = 25e3, HessianSizeMax = 500e3 ];

  // Gradation of the combined size (0: none): |grad delta| <= GradationRate on a lon/lat
  // background grid of GradationResolution degrees (the whole globe unless GradationBox[] =
  // {W, E, S, N} is set).
  DefineConstant[ GradationRate = 0, GradationResolution = 0.25 ];

  // ShoreProximity: input ShorePoints[] (point tags, e.g. Coastline{n, "Points"}: control
  // points spaced about gamma apart along every coast) and/or ShoreCurves[] (curve tags,
  // ShoreSamples uniform samples each). With ShoreBox[] = {W, E, S, N} (a Region box), points
  // on the box's edges are dropped from ShorePoints[] first: the closing pieces are open
  // sea, not coast. Output: ShoreDistanceField (the distance, metres) and ShoreField (the
  // size). A Region polygon's closing pieces follow great circles, which this test does not
  // find: take Coastline{n, "CoastPoints"} (or RegionalSea's RegionalShorePoints[]) instead.
  Macro ShoreProximity
    If (!Exists(ShorePoints[]) && !Exists(ShoreCurves[]))
      Error("ShoreProximity: set ShorePoints[] or ShoreCurves[] first");
      Abort;
    EndIf
    // Anything but 4 numbers (a polygon's vertices, a box with a number missing) would be
    // read as a box and drop the wrong points, or none.
    If (Exists(ShoreBox[]))
      If (#ShoreBox[] != 4)
        Error("ShoreProximity: ShoreBox[] holds %g numbers: it takes a box {W, E, S, N} (for a Region polygon, leave it unset and take the CoastPoints)", #ShoreBox[]);
        Abort;
      EndIf
    EndIf
    // A region's closing pieces lie on the box: their points are not coast.
    If (Exists(ShoreBox[]) && Exists(ShorePoints[]))
      shore_kept_[] = {};
      For shore_i_ In {0 : #ShorePoints[] - 1}
        shore_p_[] = Point{ShorePoints[shore_i_]};
        shore_lon_ = Atan2(shore_p_[1], shore_p_[0]) * Rad2Deg;
        shore_lat_ = Atan2(shore_p_[2], Hypot(shore_p_[0], shore_p_[1])) * Rad2Deg;
        shore_lon_ = ShoreBox[0] + Fmod(Fmod(shore_lon_ - ShoreBox[0], 360) + 360, 360);
        shore_on_box_ = Fabs(shore_lat_ - ShoreBox[2]) < 1e-5 || Fabs(shore_lat_ - ShoreBox[3]) < 1e-5;
        // A box all round the globe (the Arctic's) has no west or east side.
        If (ShoreBox[1] - ShoreBox[0] < 360)
          shore_on_box_ = shore_on_box_ || Fabs(shore_lon_ - ShoreBox[0]) < 1e-5 ||
                          Fabs(shore_lon_ - ShoreBox[1]) < 1e-5 || Fabs(shore_lon_ - ShoreBox[0] - 360) < 1e-5;
        EndIf
        If (!shore_on_box_)
          shore_kept_[] += ShorePoints[shore_i_];
        EndIf
      EndFor
      ShorePoints[] = shore_kept_[];
    EndIf
    ShoreDistanceField = newf;
    Field[ShoreDistanceField] = Distance;
    If (Exists(ShorePoints[]))
      Field[ShoreDistanceField].PointsList = {ShorePoints[]};
    EndIf
    If (Exists(ShoreCurves[]))
      Field[ShoreDistanceField].CurvesList = {ShoreCurves[]};
      Field[ShoreDistanceField].NumPointsPerCurve = ShoreSamples;
    EndIf
    ShoreField = newf;
    Field[ShoreField] = Threshold;
    Field[ShoreField].InField = ShoreDistanceField;
    Field[ShoreField].SizeMin = ShoreSizeMin;
    Field[ShoreField].SizeMax = ShoreSizeMax;
    Field[ShoreField].DistMin = ShoreDistMin;
    Field[ShoreField].DistMax = ShoreDistMax;
  Return

  // WaveLength: input BathyFile (netCDF or .asc relief, elevations positive up). Output:
  // WaveCriterionField (f1, metres) and WaveField (the size).
  Macro WaveLength
    WaveCriterionField = newf;
    Field[WaveCriterionField] = Bathymetry;
    Field[WaveCriterionField].FileName = BathyFile;
    Field[WaveCriterionField].Output = "wavelength";
    Field[WaveCriterionField].WaveLengthMin = WaveLengthMin;
    Field[WaveCriterionField].PointsPerWaveLength = PointsPerWaveLength;
    Field[WaveCriterionField].DepthRef = DepthRef;
    Field[WaveCriterionField].MinDepth = MinDepth;
    Field[WaveCriterionField].EarthRadius = EarthRadius;
    WaveField = newf;
    Field[WaveField] = Threshold;
    Field[WaveField].InField = WaveCriterionField;
    Field[WaveField].SizeMin = WaveSizeMin;
    Field[WaveField].SizeMax = WaveSizeMax;
    Field[WaveField].DistMin = WaveSizeMin;
    Field[WaveField].DistMax = WaveSizeMax;
  Return

  // BathyHessian: input BathyFile. Output: HessianCriterionField (f2, metres) and
  // HessianField (the size).
  Macro BathyHessian
    HessianCriterionField = newf;
    Field[HessianCriterionField] = Bathymetry;
    Field[HessianCriterionField].FileName = BathyFile;
    Field[HessianCriterionField].Output = "hessian";
    Field[HessianCriterionField].DepthRef = DepthRef;
    Field[HessianCriterionField].MinDepth = MinDepth;
    Field[HessianCriterionField].EarthRadius = EarthRadius;
    HessianField = newf;
    Field[HessianField] = Threshold;
    Field[HessianField].InField = HessianCriterionField;
    Field[HessianField].SizeMin = HessianSizeMin;
    Field[HessianField].SizeMax = HessianSizeMax;
    Field[HessianField].DistMin = HessianSizeMin;
    Field[HessianField].DistMax = HessianSizeMax;
  Return

  // The usual physical criteria (not the paper's): the tidal wavelength T sqrt(g H) / N
  // (T the M2 period; finer on the shelves, where the tide is slow) and the bottom slope
  // (2 pi / N) H / |grad H| (finer on steep shelf breaks and seamounts), each clamped.
  // docs/fields.md compares them with the paper's f1, which refines the abyss instead.
  DefineConstant[ TidalPeriod = 44712, TidalPointsPerWaveLength = 50, TidalSizeMin = 5e3,
                  TidalSizeMax = 500e3, SlopeParameter = 20, SlopeSizeMin = 5e3,
                  SlopeSizeMax = 500e3 ];

  // TidalWavelength: input BathyFile. Output: TidalCriterionField (T sqrt(g H) / N,
  // metres) and TidalField (the size).
  Macro TidalWavelength
    TidalCriterionField = newf;
    Field[TidalCriterionField] = Bathymetry;
    Field[TidalCriterionField].FileName = BathyFile;
    Field[TidalCriterionField].Output = "tidal";
    Field[TidalCriterionField].Period = TidalPeriod;
    Field[TidalCriterionField].PointsPerWaveLength = TidalPointsPerWaveLength;
    Field[TidalCriterionField].MinDepth = MinDepth;
    TidalField = newf;
    Field[TidalField] = Threshold;
    Field[TidalField].InField = TidalCriterionField;
    Field[TidalField].SizeMin = TidalSizeMin;
    Field[TidalField].SizeMax = TidalSizeMax;
    Field[TidalField].DistMin = TidalSizeMin;
    Field[TidalField].DistMax = TidalSizeMax;
  Return

  // BathySlope: input BathyFile. Output: SlopeCriterionField ((2 pi / N) H / |grad H|,
  // metres) and SlopeField (the size).
  Macro BathySlope
    SlopeCriterionField = newf;
    Field[SlopeCriterionField] = Bathymetry;
    Field[SlopeCriterionField].FileName = BathyFile;
    Field[SlopeCriterionField].Output = "slope";
    Field[SlopeCriterionField].PointsPerWaveLength = SlopeParameter;
    Field[SlopeCriterionField].MinDepth = MinDepth;
    Field[SlopeCriterionField].EarthRadius = EarthRadius;
    SlopeField = newf;
    Field[SlopeField] = Threshold;
    Field[SlopeField].InField = SlopeCriterionField;
    Field[SlopeField].SizeMin = SlopeSizeMin;
    Field[SlopeField].SizeMax = SlopeSizeMax;
    Field[SlopeField].DistMin = SlopeSizeMin;
    Field[SlopeField].DistMax = SlopeSizeMax;
  Return

  // OceanSize: input OceanFields[] (size fields). Output: SizeField, the Min of them
  // (FieldArgmin(SizeField, ...) tells which criterion controls the size where), limited by
  // a Gradation when GradationRate > 0 (then MinSizeField is the Min), and made the
  // Background Field.
  Macro OceanSize
    MinSizeField = newf;
    Field[MinSizeField] = Min;
    Field[MinSizeField].FieldsList = {OceanFields[]};
    SizeField = MinSizeField;
    If (GradationRate > 0)
      SizeField = newf;
      Field[SizeField] = Gradation;
      Field[SizeField].InField = MinSizeField;
      Field[SizeField].Rate = GradationRate;
      Field[SizeField].Radius = EarthRadius;
      Field[SizeField].Resolution = GradationResolution;
      If (Exists(GradationBox[]))
        Field[SizeField].LonMin = GradationBox[0];
        Field[SizeField].LonMax = GradationBox[1];
        Field[SizeField].LatMin = GradationBox[2];
        Field[SizeField].LatMax = GradationBox[3];
      EndIf
    EndIf
    Background Field = SizeField;
    // The size comes from the field alone, as in Gmsh's t10: no extension of the
    // boundary sizes into the faces (which would spread the 1D edge lengths over
    // the whole ocean), no sizes from points or curvature.
    Mesh.MeshSizeExtendFromBoundary = 0;
    Mesh.MeshSizeFromPoints = 0;
    Mesh.MeshSizeFromCurvature = 0;
  Return

  // OceanSurfaces: input OceanLoops[] (Coastline{n}) and OceanLoopsPerSurface[]
  // (Coastline{n, "LoopsPerSurface"}). Makes one Plane Surface per sea (a region box may cut
  // the water into several). Output: OceanSurfaces[].
  Macro OceanSurfaces
    OceanSurfaces[] = {};
    ocean_first_ = 0;
    For ocean_s_ In {0 : #OceanLoopsPerSurface[] - 1}
      ocean_tag_ = news;
      Plane Surface(ocean_tag_) = OceanLoops[{ocean_first_ : ocean_first_ + OceanLoopsPerSurface[ocean_s_] - 1}];
      OceanSurfaces[] += ocean_tag_;
      ocean_first_ += OceanLoopsPerSurface[ocean_s_];
    EndFor
  Return

  // EstimateTriangles: how many triangles a mesh of the size field SizeField should have,
  // before meshing: the sum over the water cells of a lon/lat grid (EstimateBox[] = {W, E,
  // S, N}, step EstimateStep degrees) of cell area / (sqrt(3)/4 h^2), the area of an
  // equilateral triangle of side h at the cell's centre. A cell is water where the depth
  // field EstimateDepthField (a Bathymetry field, Output "depth") exceeds MinDepth (land
  // reads MinDepth). The grid ignores the coastline, so islands smaller than a cell count
  // as water. Where the size is much smaller than a cell (a refined estuary), set
  // EstimateFineBox[] (edges on the coarse grid) and EstimateFineStep: that box is summed
  // on the fine grid instead. Output: EstimatedTriangles, EstimatedWaterArea (m^2).
  Macro EstimateTriangles
    EstimatedTriangles = 0;
    EstimatedWaterArea = 0;
    est_box_[] = EstimateBox[];
    est_step_ = EstimateStep;
    est_skip_[] = {1, 0, 1, 0};                  // an empty box
    If (Exists(EstimateFineBox[]))
      est_skip_[] = EstimateFineBox[];
    EndIf
    Call EstimateTrianglesOnGrid_;
    If (Exists(EstimateFineBox[]))
      est_box_[] = EstimateFineBox[];
      est_step_ = EstimateFineStep;
      est_skip_[] = {1, 0, 1, 0};
      Call EstimateTrianglesOnGrid_;
    EndIf
  Return

  Macro EstimateTrianglesOnGrid_
    est_ni_ = Round((est_box_[1] - est_box_[0]) / est_step_);
    est_nj_ = Round((est_box_[3] - est_box_[2]) / est_step_);
    For est_j_ In {0 : est_nj_ - 1}
      lat = est_box_[2] + (est_j_ + 0.5) * est_step_;
      est_area_ = EarthRadius^2 * est_step_ * Deg2Rad *
                  (Sin((lat + est_step_ / 2) * Deg2Rad) - Sin((lat - est_step_ / 2) * Deg2Rad));
      For est_i_ In {0 : est_ni_ - 1}
        lon = est_box_[0] + (est_i_ + 0.5) * est_step_;
        est_skipped_ = lon > est_skip_[0] && lon < est_skip_[1] && lat > est_skip_[2] &&
                       lat < est_skip_[3];
        If (!est_skipped_)
          Call LonLatToXYZ;
          If (FieldValue(EstimateDepthField, x, y, z) > MinDepth)
            est_h_ = FieldValue(SizeField, x, y, z);
            EstimatedWaterArea += est_area_;
            EstimatedTriangles += est_area_ / (Sqrt(3) / 4 * est_h_^2);
          EndIf
        EndIf
      EndFor
    EndFor
  Return
EndIf
