// Model -> field BuildContext: the positions and samples Distance, Restrict and
// the finite-difference kinds need, computed from geo::Model at build time.
#include "interp/builtins/field_context.h"

#include <cstdlib>
#include <optional>

namespace sm::interp {

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
  ctx.curve_samples = [m, mesh_nodes](int tag, int n) -> std::optional<std::vector<Vec3>> {
    const geo::ModelCurve* c = m->curve(std::abs(tag));
    if (!c || !c->shape) return std::nullopt;
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
