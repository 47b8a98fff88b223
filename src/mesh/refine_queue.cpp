// The shared pieces of del2d and front2d: option checks, size sampling and
// insertion bookkeeping (see refine_queue.h).
#include "mesh/refine_queue.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/geometry.h"
#include "mesh/quality.h"

namespace sm::detail {

std::string check_refine_options(const RefineOptions& opt) {
  if (!(opt.size > 0) && !opt.size_at) return "refinement needs a positive size";
  if (!(opt.radius_limit > 0)) return "refinement needs a positive radius limit";
  return {};
}

void RefineQueue::renumber(const std::vector<std::uint32_t>& new_slot, std::uint32_t slots) {
  std::vector<std::uint16_t> queued(slots, 0);
  for (std::size_t t = 0; t < new_slot.size() && t < queued_.size(); ++t)
    if (queued_[t] != 0 && new_slot[t] != TriId::kNone) queued[new_slot[t]] = queued_[t];
  queued_.swap(queued);
  for (std::vector<std::uint32_t>& b : buckets_) b.clear();
  top_ = 0;
  for (std::uint32_t t = 0; t < queued_.size(); ++t) {
    if (queued_[t] == 0) continue;
    buckets_[queued_[t] - 1].push_back(t);
    top_ = std::max<std::uint32_t>(top_, queued_[t]);
  }
}

bool RefineDriver::maybe_sort(std::vector<std::uint32_t>& new_slot, std::vector<std::uint32_t>& new_vertex) {
  if (m_.num_triangles() < next_sort_) return false;
  m_.sort_spatially(first_movable_, new_slot, new_vertex);
  queue_.renumber(new_slot, m_.num_slots());
  if (!vsize_at_.empty()) {
    // Every vertex is sized by now (each insertion's sample_sizes sized it); one that is
    // not starts again from scratch rather than read another's size.
    std::vector<double> moved(new_vertex.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t v = 0; v < vsize_at_.size() && v < new_vertex.size(); ++v) moved[new_vertex[v]] = vsize_at_[v];
    if (vsize_at_.size() != new_vertex.size()) moved.clear();
    vsize_at_.swap(moved);
  }
  next_sort_ = m_.num_triangles() > 0x7FFFFFFFu ? 0xFFFFFFFFu : 2 * m_.num_triangles();
  return true;
}

bool RefineDriver::sample_sizes(std::span<const std::uint32_t> tris, std::span<const VertexId> verts) {
  const std::size_t n = tris.size() + verts.size();
  pts_.resize(n);
  h_.resize(n);
  // A triangle flat to double precision (positive by the exact predicates, but its
  // cross product rounds to 0) has no representable circumcentre: inf or NaN. Its size is
  // taken at its centroid instead, while pts_ keeps the circumcentre, so the callers
  // see an infinite radius (the triangle is unresolved) and never a size field asked
  // about a point at infinity (which gave "mesh size must be positive and finite (got inf
  // at (inf, inf))" on two close islands). Plain triangles are evaluated as before.
  flat_.clear();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const TriId t{tris[i]};
    const Vec2 a = m_.pos(m_.vertex(t, 0)), b = m_.pos(m_.vertex(t, 1)), c = m_.pos(m_.vertex(t, 2));
    pts_[i] = circumcentre(a, b, c);
    if (!std::isfinite(pts_[i].x) || !std::isfinite(pts_[i].y)) {
      flat_.push_back({i, pts_[i]});
      pts_[i] = (1.0 / 3) * (a + b + c);
    }
  }
  for (std::size_t i = 0; i < verts.size(); ++i) pts_[tris.size() + i] = m_.pos(verts[i]);
  res_.stats.size_samples += n;
  if (opt_.size_at) opt_.size_at(pts_, h_);
  else std::fill(h_.begin(), h_.end(), opt_.size);
  if (opt_.vertex_size_at) {
    if (!size_new_vertices()) return false;
    scale_.assign(n, 1.0);
    if (opt_.vertex_size_scale) opt_.vertex_size_scale(pts_, scale_);
    for (std::size_t i = 0; i < tris.size(); ++i) h_[i] = std::min(h_[i], scale_[i] * vertex_mean(TriId{tris[i]}));
    for (std::size_t i = 0; i < verts.size(); ++i)
      h_[tris.size() + i] = std::min(h_[tris.size() + i], scale_[tris.size() + i] * vsize_at_[verts[i].value]);
  }
  for (const auto& [i, cc] : flat_) pts_[i] = cc;
  for (std::size_t i = 0; i < n; ++i) {
    const double h = h_[i];
    if (h > 0 && std::isfinite(h)) continue;
    if (res_.error.empty())
      res_.error = "mesh size must be positive and finite (got " + std::to_string(h) + " at (" +
                   std::to_string(pts_[i].x) + ", " + std::to_string(pts_[i].y) + ") in the parameter plane)";
    return false;
  }
  return true;
}

bool RefineDriver::size_new_vertices() {
  const std::uint32_t first = static_cast<std::uint32_t>(vsize_at_.size()), nv = m_.num_vertices();
  if (first >= nv) return true;
  vpts_.resize(nv - first);
  vh_.resize(nv - first);
  for (std::uint32_t v = first; v < nv; ++v) vpts_[v - first] = m_.pos(VertexId{v});
  opt_.vertex_size_at(vpts_, vh_);
  res_.stats.size_samples += vpts_.size();
  for (std::size_t i = 0; i < vh_.size(); ++i) {
    if (vh_[i] > 0) continue;   // inf (no size there) included
    if (res_.error.empty())
      res_.error = "mesh size must be positive (got " + std::to_string(vh_[i]) + " at (" + std::to_string(vpts_[i].x) +
                   ", " + std::to_string(vpts_[i].y) + ") in the parameter plane)";
    return false;
  }
  vsize_at_.insert(vsize_at_.end(), vh_.begin(), vh_.end());
  return true;
}

double RefineDriver::vertex_mean(TriId t) const {
  double sum = 0;
  int n = 0;
  for (std::uint32_t e = 0; e < 3; ++e) {
    const double h = vsize_at_[m_.vertex(t, e).value];
    if (std::isfinite(h)) sum += h, ++n;
  }
  return n ? sum / n : std::numeric_limits<double>::infinity();
}

double RefineDriver::vertex_interpolation(Vec2 p, const std::array<VertexId, 3>& c,
                                          const std::vector<double>& hv) const {
  const Vec2 a = m_.pos(c[0]), b = m_.pos(c[1]), d = m_.pos(c[2]);
  const double area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
  double w[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  if (area > 0) {
    w[0] = std::max(0.0, ((b.x - p.x) * (d.y - p.y) - (b.y - p.y) * (d.x - p.x)) / area);
    w[1] = std::max(0.0, ((d.x - p.x) * (a.y - p.y) - (d.y - p.y) * (a.x - p.x)) / area);
    w[2] = std::max(0.0, ((a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x)) / area);
  }
  double sum = 0, sum_w = 0;
  for (int k = 0; k < 3; ++k) {
    const double h = c[k].value < hv.size() ? hv[c[k].value] : std::numeric_limits<double>::infinity();
    if (std::isfinite(h)) sum += w[k] * h, sum_w += w[k];
  }
  return sum_w > 0 ? sum / sum_w : std::numeric_limits<double>::infinity();
}

double RefineDriver::size_at_point(Vec2 p, TriId t) {
  double h = opt_.size;
  ++res_.stats.size_samples;
  if (opt_.size_at) opt_.size_at(std::span<const Vec2>(&p, 1), std::span<double>(&h, 1));
  if (opt_.vertex_size_at) {
    double scale = 1;
    if (opt_.vertex_size_scale) opt_.vertex_size_scale(std::span<const Vec2>(&p, 1), std::span<double>(&scale, 1));
    h = std::min(h, scale * vertex_interpolation(p, {m_.vertex(t, 0), m_.vertex(t, 1), m_.vertex(t, 2)}, vsize_at_));
  }
  return h;
}

std::vector<std::uint32_t> RefineDriver::live_triangles() const {
  std::vector<std::uint32_t> live;
  live.reserve(m_.num_triangles());
  for (std::uint32_t t = 0; t < m_.num_slots(); ++t)
    if (m_.alive(TriId{t})) live.push_back(t);
  return live;
}

bool RefineDriver::at_vertex_limit() {
  if (m_.num_vertices() < opt_.max_vertices) return false;
  res_.error = "refinement stopped at the vertex limit";
  return true;
}

void RefineDriver::inserted() {
  ++res_.stats.inserted;
  if (opt_.vertex_size_at) {
    const VertexId v = ins_.last_vertex();
    const double h = vertex_interpolation(m_.pos(v), ins_.last_container(), vsize_at_);
    if (vsize_at_.size() <= v.value) vsize_at_.resize(v.value + 1, std::numeric_limits<double>::infinity());
    vsize_at_[v.value] = h;
  }
  queue_.grow(m_.num_slots());
  if (opt_.on_progress && res_.stats.inserted % std::max<std::uint64_t>(opt_.progress_every, 1) == 0)
    opt_.on_progress(m_.num_triangles());
}

void RefineDriver::finish() {
  m_.rebuild_out_side();
  res_.stats.pops = queue_.pops;
  res_.stats.stale += queue_.stale;
  res_.stats.walk_steps = ins_.stats.walk_steps;
  res_.stats.cavity_triangles = ins_.stats.cavity_triangles;
}

}  // namespace sm::detail
