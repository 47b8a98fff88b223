// front2d: the active front in the bucketed work list of refine_queue.h,
// Rebay's point on the front edge's bisector, Bowyer-Watson reconnection.
#include "mesh/frontal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "mesh/geometry.h"
#include "mesh/quality.h"
#include "mesh/refine_queue.h"

namespace sm {
namespace {

// A frontal point closer than this fraction of the local size to a vertex
// nearby is not used. On the unit square at h = 0.002, 0.6 gave 99.97% of
// triangles with rho > 0.9 after one smoothing pass and a min rho of 0.69
// (without the test: 99.92%, 0.55); 0.5 gave 99.94%, 0.7 the same as 0.6.
constexpr double kCrowded = 0.6;

// ratio_ of a triangle whose point Gmsh's rule refused: never served again, and not
// resolved either, so its neighbours' sides towards it are not on the front (Gmsh 4.8.4
// gives it a radius of -1: Mesh/meshGFaceDelaunayInsertion.cpp in its source tree).
constexpr float kAbandoned = -1.0f;

// Gmsh 4.8.4's rule for a new point (RefineOptions::gmsh_rejection), asked by the
// inserter once the cavity is known: each triangle (a, b, point) of the fan must keep the
// point 0.5 L from a and b, 0.4 L from the line ab when both are boundary nodes, and its
// angle at the point below acos(-0.9999); a cavity of one triangle is refused. L is the
// smaller of the means over a, b and the point of the target sizes and of the edge sizes
// (Gmsh's vSizes: on entry a vertex's shortest edge, at least half its boundary edges;
// interpolated into the triangle that gets a new vertex). Distances in plain arithmetic:
// they are size decisions.
class GmshRule final : public CavityCheck {
 public:
  GmshRule(const TriangleStore& m, const std::vector<double>& vsize, const std::vector<double>& vedge,
           std::uint32_t first_inner)
      : m_(m), vsize_(vsize), vedge_(vedge), first_inner_(first_inner) {}
  double point_size = 0, point_edge = 0;  // the point's sizes, set before each insertion
  bool accept(Vec2 p, std::size_t triangles, std::span<const CavityEdge> boundary) override {
    if (triangles == 1) return false;
    for (const CavityEdge& e : boundary) {
      const Vec2 a = m_.pos(e.a), b = m_.pos(e.b);
      const double l = std::min(vsize_[e.a.value] + vsize_[e.b.value] + point_size,
                                vedge_[e.a.value] + vedge_[e.b.value] + point_edge) /
                       3;
      const double d1 = norm(a - p), d2 = norm(b - p), d3 = norm(b - a);
      if (d1 < 0.5 * l || d2 < 0.5 * l) return false;
      if (e.a.value < first_inner_ && e.b.value < first_inner_ && std::abs(cross(b - a, p - a)) < 0.4 * l * d3)
        return false;
      if (d1 * d1 + d2 * d2 - d3 * d3 < -0.9999 * 2 * d1 * d2) return false;
    }
    return true;
  }

 private:
  const TriangleStore& m_;
  const std::vector<double>& vsize_;
  const std::vector<double>& vedge_;
  std::uint32_t first_inner_;  // vertices below it were present on entry: boundary nodes
};

class Frontal : detail::RefineDriver {
 public:
  Frontal(TriangleStore& m, const RefineOptions& opt, FrontalResult& res)
      : RefineDriver(m, opt, res), fres_(res), rule_(m, vsize_, vedge_, m.num_vertices()) {}
  void run();

 private:
  bool resolved(std::uint32_t t) const { return ratio_[t] >= 0 && ratio_[t] <= limit2_; }
  bool abandoned(std::uint32_t t) const { return ratio_[t] < 0; }
  /// Rebay's point on each front side of t from s on, else t's circumcentre.
  // The k-th side of t from s (s itself, then the others only on the front) and its
  // Rebay point, when that point lies in t's circumcircle.
  bool front_candidate(std::uint32_t t, Side s, std::uint32_t k, Side& fs, Vec2& x);
  InsertOutcome insert_rebay(std::uint32_t t, Side s);
  /// The same points under Gmsh's rule: Rejected as soon as it refuses one.
  InsertOutcome insert_gmsh(std::uint32_t t, Side s);
  /// x inserted from t under Gmsh's rule.
  InsertOutcome insert_checked(Vec2 x, std::uint32_t t);
  /// The front side of unresolved t: a constrained or hull side, or one
  /// whose neighbour is resolved (first in side order); kNone if t is not
  /// on the front.
  Side front_side(std::uint32_t t) const;
  bool on_front(Side s) const;
  /// Rebay's point for front side s (see frontal.h).
  Vec2 frontal_point(Side s) const;
  /// Whether x is closer than kCrowded times the size to a corner of s's
  /// triangle or to the apex of one of its neighbours.
  bool crowds_vertex(Side s, Vec2 x) const;
  void push(std::uint32_t t) { queue_.push(t, ratio_[t]); }
  /// Queues the unresolved neighbours of resolved t that are not queued.
  void wake_neighbours(std::uint32_t t);
  /// Sizes of the triangles in `tris` (at their circumcentres) and of the
  /// vertices in `verts`, from one size_at call. False on a bad size.
  bool evaluate(std::span<const std::uint32_t> tris, std::span<const VertexId> verts);
  /// Classifies freshly sized triangles and queues those on the front.
  void classify(std::span<const std::uint32_t> tris);
  void grow_slots();
  /// vedge_ of the vertices present on entry (GmshRule).
  void init_edge_sizes();
  /// Moves the per-slot ratios and per-vertex sizes after sort_spatially.
  void renumber(const std::vector<std::uint32_t>& new_slot, const std::vector<std::uint32_t>& new_vertex);

  FrontalResult& fres_;
  double limit2_ = 0;
  std::vector<float> ratio_;   // per slot: R^2 / h^2
  std::vector<double> vsize_;  // per vertex: target size
  std::vector<double> vedge_;  // per vertex, with gmsh_rejection: Gmsh's edge size (GmshRule)
  GmshRule rule_;              // reads vsize_ and vedge_
};

bool Frontal::on_front(Side s) const {
  const Side o = m_.twin[s.value];
  return !o.valid() || m_.constrained(s) || resolved(o.value / 3);
}

Side Frontal::front_side(std::uint32_t t) const {
  for (std::uint32_t e = 0; e < 3; ++e)
    if (on_front(Side{3 * t + e})) return Side{3 * t + e};
  return Side{};
}

bool Frontal::crowds_vertex(Side s, Vec2 x) const {
  const double h = kCrowded * 0.5 * (vsize_[m_.org(s).value] + vsize_[m_.dest(s).value]);
  const std::uint32_t t = s.value / 3;
  for (std::uint32_t e = 0; e < 3; ++e) {
    if (norm2(m_.pos(m_.vertex(TriId{t}, e)) - x) < h * h) return true;
    const Side o = m_.twin[3 * t + e];
    if (o.valid() && norm2(m_.pos(m_.apex(o)) - x) < h * h) return true;
  }
  return false;
}

Vec2 Frontal::frontal_point(Side s) const {
  const VertexId ia = m_.org(s), ib = m_.dest(s);
  const Vec2 a = m_.pos(ia), b = m_.pos(ib);
  const Vec2 cc = circumcentre(a, b, m_.pos(m_.apex(s)));
  const Vec2 mid = 0.5 * (a + b), e = b - a;
  const double len = norm(e), p = 0.5 * len;
  const Vec2 n = (1 / len) * Vec2{-e.y, e.x};  // towards the apex: the triangle is counter-clockwise
  const double q = dot(cc - mid, n);
  // The circumradius of an equilateral triangle of side h is h / sqrt 3.
  double rho_m = std::max(0.5 * (vsize_[ia.value] + vsize_[ib.value]) / std::sqrt(3.0), p);
  if (q > 0) rho_m = std::min(rho_m, (p * p + q * q) / (2 * q));
  const double d = rho_m + std::sqrt(std::max(0.0, rho_m * rho_m - p * p));
  return mid + d * n;
}

void Frontal::wake_neighbours(std::uint32_t t) {
  for (std::uint32_t e = 0; e < 3; ++e) {
    const Side s{3 * t + e};
    const Side o = m_.twin[s.value];
    if (!o.valid()) continue;
    const std::uint32_t nt = o.value / 3;
    if (!resolved(nt) && !abandoned(nt) && !queue_.queued(nt)) push(nt);
  }
}

void Frontal::grow_slots() {
  if (ratio_.size() < m_.num_slots()) ratio_.resize(m_.num_slots(), 0.0f);
  queue_.grow(m_.num_slots());
  if (vsize_.size() < m_.num_vertices()) vsize_.resize(m_.num_vertices(), 0.0);
}

bool Frontal::evaluate(std::span<const std::uint32_t> tris, std::span<const VertexId> verts) {
  if (!sample_sizes(tris, verts)) return false;
  for (std::size_t i = 0; i < verts.size(); ++i) vsize_[verts[i].value] = h_[tris.size() + i];
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const std::uint32_t t = tris[i];
    const double r2 = norm2(pts_[i] - m_.pos(m_.vertex(TriId{t}, 0)));
    // Never 0: the work list takes positive priorities only.
    ratio_[t] = std::max(static_cast<float>(r2 / (h_[i] * h_[i])), 1e-30f);
    queue_.drop(t);
  }
  return true;
}

void Frontal::classify(std::span<const std::uint32_t> tris) {
  for (const std::uint32_t t : tris) {
    if (!resolved(t)) {
      if (!queue_.queued(t) && front_side(t).valid()) push(t);
    } else {
      wake_neighbours(t);
    }
  }
}

void Frontal::renumber(const std::vector<std::uint32_t>& new_slot, const std::vector<std::uint32_t>& new_vertex) {
  std::vector<float> ratio(m_.num_slots(), 0.0f);
  for (std::size_t t = 0; t < new_slot.size() && t < ratio_.size(); ++t)
    if (new_slot[t] != TriId::kNone) ratio[new_slot[t]] = ratio_[t];
  ratio_.swap(ratio);
  std::vector<double> vsize(vsize_.size());
  for (std::size_t v = 0; v < vsize_.size(); ++v) vsize[new_vertex[v]] = vsize_[v];
  vsize_.swap(vsize);
  if (!vedge_.empty()) {
    std::vector<double> vedge(vedge_.size());
    for (std::size_t v = 0; v < vedge_.size(); ++v) vedge[new_vertex[v]] = vedge_[v];
    vedge_.swap(vedge);
  }
}

void Frontal::init_edge_sizes() {
  vedge_.assign(m_.num_vertices(), std::numeric_limits<double>::infinity());
  for (const std::uint32_t t : live_triangles())
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      const VertexId a = m_.org(s), b = m_.dest(s);
      const double l = norm(m_.pos(b) - m_.pos(a));
      vedge_[a.value] = std::min(vedge_[a.value], l);
      vedge_[b.value] = std::min(vedge_[b.value], l);
    }
  // A short boundary edge does not make its ends' sizes smaller than half of it (as Gmsh
  // keeps small curve edges from polluting the sizes).
  for (const std::uint32_t t : live_triangles())
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Side s{3 * t + e};
      if (!m_.constrained(s) && m_.twin[s.value].valid()) continue;
      const VertexId a = m_.org(s), b = m_.dest(s);
      const double l = 0.5 * norm(m_.pos(b) - m_.pos(a));
      vedge_[a.value] = std::max(vedge_[a.value], l);
      vedge_[b.value] = std::max(vedge_[b.value], l);
    }
}

bool Frontal::front_candidate(std::uint32_t t, Side s, std::uint32_t k, Side& fs, Vec2& x) {
  fs = Side{3 * t + (s.value - 3 * t + k) % 3};
  if (k > 0 && !on_front(fs)) return false;
  x = frontal_point(fs);
  // The point must be in t's circumcircle, or t would survive the insertion and come
  // back forever.
  return incircle(m_.pos(m_.org(fs)), m_.pos(m_.dest(fs)), m_.pos(m_.apex(fs)), x, &res_.stats.predicates) ==
         Sign::Positive;
}

InsertOutcome Frontal::insert_rebay(std::uint32_t t, Side s) {
  InsertOutcome out = InsertOutcome::Outside;
  // Rebay's point on each front side in turn (a side beside a constraint
  // may put it beyond another one in a narrow passage). A point crowding
  // a vertex means two fronts meet here: the circumcentre closes the gap
  // better (it is what lifts the seams' worst rho from 0.27 to 0.63).
  bool crowded = false;
  for (std::uint32_t k = 0; k < 3 && out != InsertOutcome::Inserted && !crowded; ++k) {
    Side fs{};
    Vec2 x{};
    if (!front_candidate(t, s, k, fs, x)) continue;
    if ((crowded = crowds_vertex(fs, x))) break;
    out = ins_.insert_near(x, TriId{t});
    if (out == InsertOutcome::Inserted) ++fres_.frontal_points;
  }
  if (out != InsertOutcome::Inserted) {
    const TriId tt{t};
    out = ins_.insert_near(circumcentre(m_.pos(m_.vertex(tt, 0)), m_.pos(m_.vertex(tt, 1)), m_.pos(m_.vertex(tt, 2))),
                           tt);
    if (out == InsertOutcome::Inserted) ++fres_.circumcentre_fallbacks;
  }
  return out;
}

InsertOutcome Frontal::insert_checked(Vec2 x, std::uint32_t t) {
  const TriId tt = ins_.locate(x, TriId{t});
  if (!tt.valid()) return InsertOutcome::Outside;
  rule_.point_size = size_at_point(x, tt);
  rule_.point_edge = vertex_interpolation(x, {m_.vertex(tt, 0), m_.vertex(tt, 1), m_.vertex(tt, 2)}, vedge_);
  return ins_.insert(x, tt, &rule_);
}

InsertOutcome Frontal::insert_gmsh(std::uint32_t t, Side s) {
  InsertOutcome out = InsertOutcome::Outside;
  for (std::uint32_t k = 0; k < 3; ++k) {
    Side fs{};
    Vec2 x{};
    if (!front_candidate(t, s, k, fs, x)) continue;
    out = insert_checked(x, t);
    if (out == InsertOutcome::Inserted) ++fres_.frontal_points;
    if (out == InsertOutcome::Inserted || out == InsertOutcome::Rejected) return out;
  }
  const TriId tt{t};
  out = insert_checked(circumcentre(m_.pos(m_.vertex(tt, 0)), m_.pos(m_.vertex(tt, 1)), m_.pos(m_.vertex(tt, 2))), t);
  if (out == InsertOutcome::Inserted) ++fres_.circumcentre_fallbacks;
  return out;
}

void Frontal::run() {
  limit2_ = opt_.radius_limit * opt_.radius_limit;
  grow_slots();
  {
    std::vector<VertexId> verts;
    for (std::uint32_t v = 0; v < m_.num_vertices(); ++v) verts.push_back(VertexId{v});
    for (std::size_t i = 0; i < verts.size(); i += 4096)
      if (!evaluate({}, std::span<const VertexId>(verts.data() + i, std::min<std::size_t>(4096, verts.size() - i))))
        return finish();
  }
  if (opt_.gmsh_rejection) init_edge_sizes();
  const std::vector<std::uint32_t> live = live_triangles();
  for (std::size_t i = 0; i < live.size(); i += 4096)
    if (!evaluate(std::span<const std::uint32_t>(live.data() + i, std::min<std::size_t>(4096, live.size() - i)), {}))
      return finish();
  // Only unresolved triangles touching the boundary or a resolved one start
  // on the front; the others join it as their neighbours get resolved.
  for (const std::uint32_t t : live)
    if (!resolved(t) && front_side(t).valid()) push(t);
  std::vector<std::uint32_t> new_slot, new_vertex;
  std::uint32_t t;
  while (queue_.pop(m_, t)) {
    const Side s = front_side(t);
    if (!s.valid()) {  // left the front since it was queued; a resolved neighbour will queue it again
      ++res_.stats.stale;
      continue;
    }
    if (at_vertex_limit()) break;
    const InsertOutcome out = opt_.gmsh_rejection ? insert_gmsh(t, s) : insert_rebay(t, s);
    if (out == InsertOutcome::Rejected) {
      ++res_.stats.rejected;
      ++fres_.gmsh_rejected;
      ratio_[t] = kAbandoned;
      continue;
    }
    if (out != InsertOutcome::Inserted) {
      ++res_.stats.rejected;
      ++fres_.given_up;
      ratio_[t] = 1e-30f;  // accepted as it is: its neighbours now see a resolved triangle
      wake_neighbours(t);
      continue;
    }
    inserted();
    grow_slots();
    const VertexId v = ins_.last_vertex();
    if (opt_.gmsh_rejection) {
      if (vedge_.size() <= v.value) vedge_.resize(v.value + 1, std::numeric_limits<double>::infinity());
      vedge_[v.value] = vertex_interpolation(m_.pos(v), ins_.last_container(), vedge_);
    }
    if (!evaluate(ins_.created(), std::span<const VertexId>(&v, 1))) break;
    classify(ins_.created());
    if (maybe_sort(new_slot, new_vertex)) {
      renumber(new_slot, new_vertex);
      new_slot = {}, new_vertex = {};  // 6 bytes a triangle, not needed until the next sort
    }
  }
  finish();
}

}  // namespace

FrontalResult refine_front2d(TriangleStore& m, const RefineOptions& opt) {
  FrontalResult res;
  res.error = detail::check_refine_options(opt);
  if (!res.ok()) return res;
  Frontal f(m, opt, res);
  f.run();
  return res;
}

}  // namespace sm
