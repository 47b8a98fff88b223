// What size fields read from the geometry model when they are built
// (docs/fields.md): point positions, Gmsh's Distance samples of curves and
// the bounding-box diagonal, as the kernel's model-free BuildContext.
#pragma once

#include <filesystem>
#include <map>
#include <span>
#include <vector>

#include "base/vec.h"
#include "field/registry.h"
#include "geo/model.h"

namespace sm::interp {

/// Interior mesh nodes of each meshed curve (tag > 0 -> nodes), which Gmsh's
/// Distance samples before its uniform points once the 1D mesh exists.
using CurveMeshNodes = std::map<int, std::vector<Vec3>>;

/// Gmsh 4.8.4's Distance samples of a curve: its m interior mesh nodes, then
/// K - 2 points at the uniform parameters t = i/(K-1), i = 1..K-2, where
/// K = n - m (end points excluded; for an unmeshed curve n - 2 points).
std::vector<Vec3> distance_curve_samples(const geo::Curve& c, int n,
                                         std::span<const Vec3> mesh_nodes = {});

/// Gmsh's CTX::lc: the model's bounding-box diagonal, 1 when the box is empty
/// or degenerate.
double model_bbox_diag(const geo::Model& model);

/// A BuildContext reading `model`, which must outlive every build made with
/// it. Relative data files resolve against `base_dir` (field options holding
/// file names are already made script-relative when they are set).
/// With `mesh_nodes` (which must outlive the builds too), meshed curves are
/// sampled as Gmsh samples them during 2D meshing.
field::BuildContext make_build_context(const geo::Model& model, std::filesystem::path base_dir = {},
                                       const CurveMeshNodes* mesh_nodes = nullptr);

}  // namespace sm::interp
