// The BoundaryLayer field's parameters as plain data, for the meshers (mesh/face_layer.h,
// mesh1d.cpp), and the growth of its layers: Gmsh 4.8.4's BoundaryLayer field
// (docs/fields.md). As a size field it is Gmsh's scalar value; the layers themselves are
// built by the 2D mesher for each field named by `BoundaryLayer Field = n;`.
#pragma once

#include <vector>

#include "field/options.h"

namespace sm::field {

/// Most layers one column may get (the option checks refuse more: Size 1e-9 with Ratio 1
/// over Thickness 1 would ask for 10^9).
inline constexpr int kMaxBoundaryLayers = 1000;

struct BoundaryLayerParams {
  std::vector<int> curves;             ///< CurvesList: the curves that get layers
  std::vector<int> end_points;         ///< PointsList: where layers end (1D: adjacent lines get layer points)
  std::vector<int> fan_points;         ///< FanPointsList: fans of columns there
  std::vector<int> fan_sizes;          ///< FanPointsSizesList (one per fan point, else Mesh.BoundaryLayerFanElements)
  std::vector<int> excluded_surfaces;  ///< ExcludedSurfacesList
  std::vector<std::pair<int, double>> point_sizes;  ///< SizesList: (point, first layer height)
  double size = 0.1;       ///< Size: height of the first layer
  double size_far = 1;     ///< SizeFar
  double ratio = 1.1;      ///< Ratio: growth of successive layers
  double thickness = 0.01; ///< Thickness: the layers stop below it
  double aniso_max = 1e10;
  bool quads = false;      ///< Quads: quadrangles (else each split into two triangles)
  bool intersect_metrics = false;
  bool beta_law = false;   ///< BetaLaw: NbLayers heights of Gmsh's beta law, instead of Ratio
  double beta = 1.01;
  int nb_layers = 10;

  bool has_curve(int tag) const;
  bool is_fan_point(int tag) const;
  bool is_end_point(int tag) const;
  bool excludes(int surface) const;
  /// Elements of the fan at point `tag` per half turn (Gmsh's fanSize: the list's entry
  /// when the list is as long as FanPointsList, else `default_elements`).
  int fan_size(int tag, int default_elements) const;
  /// The first layer's height at model point `tag` (SizesList, else Size).
  double size_at_point(int tag) const;
};

/// The parameters of a BoundaryLayer field's options, checked: a FieldError BadValue
/// (field `id`, the option) for a value the layers cannot be built with.
BoundaryLayerParams boundary_layer_params(const Options& o, int id);

/// The distances from the wall of the layer points of one column whose first layer is
/// `first` high: first, first(1 + r), first(1 + r + r^2), ... while at most `limit`
/// (Gmsh 4.8.4's loop in Geo/boundaryLayersData.cpp: a distance above the limit ends
/// the column); with the beta law, NbLayers distances first * t_i / t_0, no limit. At
/// most kMaxBoundaryLayers.
std::vector<double> layer_distances(const BoundaryLayerParams& p, double first, double limit);

}  // namespace sm::field
