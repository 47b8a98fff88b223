// What size fields read from the geometry model when they are built
// (gmsh-reference 4.1): point positions, Gmsh's Distance samples of curves and
// the bounding-box diagonal, as the kernel's model-free BuildContext.
#pragma once

#include <filesystem>
#include <vector>

#include "base/vec.h"
#include "field/registry.h"
#include "geo/model.h"

namespace sm::interp {

/// Gmsh 4.8.4's Distance samples of an unmeshed curve: n - 2 points at the
/// uniform parameters t = i/(n-1), i = 1..n-2 (end points excluded; none for
/// n < 3). Once the curve is meshed Gmsh adds its interior nodes instead.
std::vector<Vec3> distance_curve_samples(const geo::Curve& c, int n);

/// Gmsh's CTX::lc: the model's bounding-box diagonal, 1 when the box is empty
/// or degenerate.
double model_bbox_diag(const geo::Model& model);

/// A BuildContext reading `model`, which must outlive every build made with
/// it. Relative data files resolve against `base_dir` (field options holding
/// file names are already made script-relative when they are set).
field::BuildContext make_build_context(const geo::Model& model, std::filesystem::path base_dir = {});

}  // namespace sm::interp
