// Gmsh's final element size at a point (BGM_MeshSize, docs/fields.md):
// bbox lc, point sizes, curvature, background field, Min/Max clamp, factor.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string_view>

#include "field/channel_width.h"
#include "field/field.h"

namespace sm::field {

/// Mesh.MeshSize* options (CharacteristicLength* are the deprecated aliases).
struct SizePolicyOptions {
  double factor = 1;                 ///< MeshSizeFactor (-clscale)
  double min = 0;                    ///< MeshSizeMin
  double max = 1e22;                 ///< MeshSizeMax
  bool from_points = true;           ///< MeshSizeFromPoints
  int extend_from_boundary = 1;      ///< MeshSizeExtendFromBoundary
  int from_curvature = 0;            ///< MeshSizeFromCurvature: N elements per 2*pi radius
};

/// Sets option `name` ("MeshSizeMin", "CharacteristicLengthMin", with or
/// without the "Mesh." prefix). Returns false if `name` is not one of them.
bool set_size_option(SizePolicyOptions& o, std::string_view name, double value);

/// What is known at the point being sized. Sizes that do not apply stay
/// nullopt (e.g. no background field).
struct SizeQuery {
  double bbox_diag = 0;              ///< model bounding-box diagonal (CTX::lc); 0 or less: 1
  int entity_dim = 2;                ///< 0 point, 1 curve, 2 surface
  /// From points: on a point its lc; on a curve the lc of each end point
  /// (nullopt where the point has none) and the curve parameter t in [0,1].
  std::optional<double> point_lc;
  std::optional<double> end_lc0, end_lc1;
  double t = 0;
  std::optional<double> curvature;   ///< kappa of the curve / max of the surface
  std::optional<double> background;  ///< background field value
  std::optional<double> entity_size; ///< l4/l5: per-entity sizes set through the API
  double entity_factor = 1;          ///< per-entity size factor
};

struct SizeResult {
  double size = 0;
  /// The clamped size was not positive: Gmsh reports an error and uses bbox.
  bool nonpositive = false;
};

SizeResult final_size(const SizePolicyOptions& o, const SizeQuery& q);

/// With MeshSizeExtendFromBoundary, the 2D target is min(interpolated
/// boundary size, final size); without, the final size only.
double surface_target(const SizePolicyOptions& o, double final, std::optional<double> boundary_interp);

/// The background field with an extra criterion inside its Min on some entities only
/// (Mesh.ElementsAcrossChannels: the ChannelWidth of the coast on the surfaces a
/// coastline bounds and on their curves). `base` may be null (no background field):
/// then the extra criterion alone, and "no constraint" (MAX_LC) elsewhere. Points
/// without an entity get the extra criterion too.
std::shared_ptr<const SizeField> min_on_entities(std::shared_ptr<const SizeField> base,
                                                 std::shared_ptr<const ChannelWidthField> extra, std::set<int> curves,
                                                 std::set<int> surfaces);

}  // namespace sm::field
