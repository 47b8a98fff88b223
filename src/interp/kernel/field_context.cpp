// Model -> field BuildContext: the positions and samples Distance, Restrict and
// the finite-difference kinds need, computed from geo::Model at build time.
#include "interp/kernel/field_context.h"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "field/error.h"

namespace sm::interp {

namespace {
constexpr std::size_t kMaxCurveSamples = 50'000'000;
}  // namespace

std::vector<Vec3> distance_curve_samples(const geo::Curve& c, int n, std::span<const Vec3> mesh_nodes) {
  std::vector<Vec3> out(mesh_nodes.begin(), mesh_nodes.end());
  const long k = static_cast<long>(n) - static_cast<long>(mesh_nodes.size());
  for (long i = 1; i < k - 1; ++i) out.push_back(c.point(static_cast<double>(i) / static_cast<double>(k - 1)));
  return out;
}

double model_bbox_diag(const geo::Model& model) {
  const double d = model.bounding_box().diagonal();
  return d > 0 ? d : 1.0;
}

field::BuildContext make_build_context(const geo::Model& model, std::filesystem::path base_dir,
                                       const CurveMeshNodes* mesh_nodes) {
  field::BuildContext ctx;
  ctx.bbox_diag = model_bbox_diag(model);
  ctx.base_dir = std::move(base_dir);
  const geo::Model* m = &model;
  ctx.point_position = [m](int tag) -> std::optional<Vec3> {
    const geo::ModelVertex* v = m->vertex(tag);
    if (!v) return std::nullopt;
    return v->xyz;
  };
  // A negative tag names the reversed curve: the same samples (Gmsh's FindCurve(-tag)).
  // A hostile NumPointsPerCurve must not exhaust memory: the samples of one
  // build stay below kMaxCurveSamples (1.2 GB), well above real coastlines.
  auto total = std::make_shared<std::size_t>(0);
  ctx.curve_samples = [m, mesh_nodes, total](int tag, int n) -> std::optional<std::vector<Vec3>> {
    const geo::ModelCurve* c = m->curve(std::abs(tag));
    if (!c || !c->shape) return std::nullopt;
    *total += static_cast<std::size_t>(std::max(n, 0));
    if (*total > kMaxCurveSamples) {
      field::FieldError e(field::FieldErrc::BadValue,
                          fmt::format("NumPointsPerCurve: more than {} curve samples in one build",
                                      kMaxCurveSamples));
      e.option = "NumPointsPerCurve";
      throw e;
    }
    std::span<const Vec3> nodes;
    if (mesh_nodes) {
      auto it = mesh_nodes->find(std::abs(tag));
      if (it != mesh_nodes->end()) nodes = it->second;
    }
    return distance_curve_samples(*c->shape, n, nodes);
  };
  // Surface point clouds need a surface parametrisation the model does not
  // expose yet (Gmsh >= 4.9 samples only OCC and discrete surfaces anyway):
  // SurfacesList is reported as "cannot be sampled" by the Distance field.
  return ctx;
}

}  // namespace sm::interp
