// The target size of a face in its plane (face_sizing.h): the boundary sizes, their
// barycentric interpolation in the recovered boundary triangulation, the size policy.
#include "mesh/face_sizing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/predicates.h"
#include "mesh/locate.h"

namespace sm {

void set_boundary_sizes(FaceSizing& f, TriangleStore recovered, std::uint32_t fixed_count,
                        std::span<const Edge> edges, std::span<const std::uint32_t> global, const ModelMesh& mesh,
                        const geo::Model& model, bool coarse) {
  if (f.size.extend_from_boundary == 0) return;
  f.bg = std::move(recovered);
  std::vector<double>& bsize = f.bsize;
  bsize.assign(fixed_count, 0.0);
  std::vector<std::uint32_t> count(fixed_count, 0);
  std::vector<double> node_h;
  if (coarse) {
    node_h.assign(mesh.nodes.size(), 0.0);
    for (const auto& [ct, cm] : mesh.curves)
      for (std::size_t k = 0; k < cm.h.size() && k < cm.nodes.size(); ++k) node_h[cm.nodes[k]] = cm.h[k];
  }
  auto edge_length = [&](std::uint32_t ga, std::uint32_t gb) {
    if (coarse && node_h[ga] > 0 && node_h[gb] > 0) return 0.5 * (node_h[ga] + node_h[gb]);
    return norm(mesh.nodes[ga].xyz - mesh.nodes[gb].xyz);
  };
  for (const Edge& e : edges) {
    const double len = edge_length(global[e.first.value], global[e.second.value]);
    bsize[e.first.value] += len, bsize[e.second.value] += len;
    ++count[e.first.value], ++count[e.second.value];
  }
  for (std::uint32_t v = 0; v < fixed_count; ++v) {
    bsize[v] = count[v] ? bsize[v] / count[v] : std::numeric_limits<double>::infinity();
    if (!count[v]) {
      for (const auto& [vt, node] : mesh.vertex_node)
        if (node == global[v]) {
          const geo::ModelVertex* mv = model.vertex(vt);
          if (mv && f.size.from_points && mv->lc < geo::kMaxLc) bsize[v] = mv->lc * f.size.factor;
          break;
        }
    }
  }
}

// Barycentric interpolation of the boundary sizes in the recovered boundary
// triangulation (holes and hull included): the walk of mesh/locate.h from the last hit,
// passing over hull sides, so a point beyond the hull is clamped to the triangle where
// the walk ends.
std::optional<double> PlaneSizes::boundary_size(Vec2 p) {
  const TriangleStore& bg = f_.bg;
  const std::vector<double>& bsize = f_.bsize;
  if (!hint_.valid() || !bg.alive(hint_)) {
    hint_ = TriId{};
    for (std::uint32_t t = 0; t < bg.num_slots(); ++t)
      if (bg.alive(TriId{t})) {
        hint_ = TriId{t};
        break;
      }
    if (!hint_.valid()) return std::nullopt;
  }
  // The first side turns at every step (mesh/locate.h): the triangulation is not
  // Delaunay, where a fixed order could cycle.
  struct Walker : StoreWalker {
    std::uint32_t& turn;
    std::uint32_t first_side(std::uint32_t, std::uint64_t) const { return turn = (turn + 1) % 3; }
  } w{{bg, nullptr, false, true}, walk_turn_};
  const WalkResult r = walk_to(w, p, hint_.value, bg.num_slots());
  TriId t{r.tri};
  if (r.end == WalkEnd::StepLimit)
    if (const TriId found = scan_for(w, p, hint_); found.valid()) t = found;
  hint_ = t;
  const std::array<double, 3> weight =
      barycentric(bg.pos(bg.vertex(t, 0)), bg.pos(bg.vertex(t, 1)), bg.pos(bg.vertex(t, 2)), p);
  double sum_w = 0, sum = 0;
  for (std::uint32_t e = 0; e < 3; ++e) {
    const std::uint32_t v = bg.vertex(t, e).value;
    const double h = v < bsize.size() ? bsize[v] : std::numeric_limits<double>::infinity();
    const double wi = std::max(0.0, weight[e]);
    if (!std::isfinite(h)) continue;
    sum_w += wi;
    sum += wi * h;
  }
  if (sum_w > 0) return sum / sum_w;
  double lo = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = 0; e < 3; ++e)
    if (bg.vertex(t, e).value < bsize.size()) lo = std::min(lo, bsize[bg.vertex(t, e).value]);
  return std::isfinite(lo) ? std::optional<double>(lo) : std::nullopt;
}

void PlaneSizes::on_surface(std::span<const Vec2> p, std::span<double> h) {
  if (part_ == Part::ExtensionOnly) {
    const bool extend = f_.size.extend_from_boundary != 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::optional<double> b = extend ? boundary_size(p[i]) : std::nullopt;
      h[i] = b ? *b : std::numeric_limits<double>::infinity();
    }
    if (evaluations_) evaluations_->fetch_add(p.size(), std::memory_order_relaxed);
    return;
  }
  pts3_.resize(p.size());
  field_.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) pts3_[i] = f_.plane.to_space(p[i]);
  if (f_.background) f_.background->eval_on(field::EntityRef{2, f_.tag}, pts3_, field_);
  field::SizeQuery q;
  q.bbox_diag = f_.bbox;
  q.entity_dim = 2;
  const bool extend = f_.size.extend_from_boundary != 0 && part_ == Part::All;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (f_.background) q.background = field_[i];
    double size = field::final_size(f_.size, q).size;
    if (extend) size = field::surface_target(f_.size, size, boundary_size(p[i]));
    h[i] = size;
  }
  if (evaluations_) evaluations_->fetch_add(p.size(), std::memory_order_relaxed);
}

void PlaneSizes::operator()(std::span<const Vec2> p, std::span<double> h) {
  on_surface(p, h);
  for (std::size_t i = 0; i < p.size(); ++i) h[i] /= f_.plane.lambda(p[i]);
}

SizeAt3 target_size_fn(std::shared_ptr<const FaceSizing> sizing) {
  // A PlaneSizes per call (its walk hint and scratch are the call's own), so that the
  // statistics can call it from several threads on batches of fixed bounds: the sizes of
  // a batch then do not depend on which batches ran before on the same thread.
  return [sizing](std::span<const Vec3> x, std::span<double> h) {
    std::vector<Vec2> plane_pts(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) plane_pts[i] = sizing->plane.plane_of_space(x[i]);
    PlaneSizes sizes(*sizing);
    sizes.on_surface(plane_pts, h);
  };
}

}  // namespace sm
