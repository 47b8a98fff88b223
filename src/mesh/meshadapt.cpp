// meshadapt: rounds of passes over the edges. Each pass collects its
// candidates first (edges too long, or too short, in the size field), sorts
// them (longest or shortest first, ties by side id) and applies them with
// triangle marks so that a triangle changes at most once per pass: the
// split pass is a longest-edge bisection round, the collapse pass removes
// an independent set of short edges.
#include "mesh/meshadapt.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "mesh/modify/collapse.h"
#include "mesh/modify/split.h"
#include "mesh/modify/swap.h"

namespace sm {
namespace {

constexpr double kLongEdge = 1.4142135623730951;   // split above sqrt2
constexpr double kShortEdge = 0.7071067811865476;  // collapse below 1/sqrt2
// Rounds without a new low in the number of splits and collapses before the
// loop stops: a split and a collapse can undo each other round after round
// (smoothing stretches the edge a collapse made), and the few edges left out
// of range are then boxed in by fixed vertices or by the quality guards.
constexpr int kStallRounds = 4;

class Adapter {
 public:
  Adapter(TriangleStore& m, const MeshAdaptOptions& opt, MeshAdaptResult& res) : m_(m), opt_(opt), res_(res) {}
  void run();

 private:
  PredicateStats* pst() { return &res_.stats.predicates; }
  void after(const char* pass) const {
    if (opt_.after_pass) opt_.after_pass(m_, pass);
  }
  /// Length in the size field: |ab| times the trapezoid mean of 1/h.
  double length(VertexId a, VertexId b) const {
    return std::sqrt(norm2(m_.pos(b) - m_.pos(a))) * 0.5 * (inv_h_[a.value] + inv_h_[b.value]);
  }
  void evaluate(const std::vector<std::uint32_t>& verts);
  void evaluate_from(std::uint32_t first);
  void mark(TriId t);
  void mark_ball(VertexId v);
  void clear_marks();
  std::uint64_t split_pass();
  std::uint64_t collapse_pass();
  /// Smallest rho of v's ball with v at p (ring from vertex_ring).
  double ball_min_rho(const std::vector<Side>& ring, Vec2 p) const;
  /// min rho of v's ball after a collapse onto w, or -1 when a new edge
  /// would be too long; ring_ holds v's ring.
  double collapse_quality(VertexId w) const;
  /// Swaps for quality from the edges of the triangles round the dirty
  /// vertices (all edges when `all`); swapped corners become dirty.
  std::uint64_t swap_pass(bool all);
  /// Smooths the dirty vertices (all when `all`) and clears them; a vertex
  /// that moved by more than 1% of its size dirties its neighbours for the
  /// next round, so quiet regions stop costing time.
  std::uint64_t smooth_pass(bool all);
  void touch(VertexId v) {
    if (!dirty_[v.value]) dirty_[v.value] = 1, dirty_list_.push_back(v.value);
  }

  TriangleStore& m_;
  const MeshAdaptOptions& opt_;
  MeshAdaptResult& res_;
  std::vector<double> inv_h_;          // per vertex: 1 / size
  std::vector<std::uint8_t> fixed_;    // per vertex: never moved or removed
  std::vector<std::uint64_t> cand_;    // {length bits, side}
  std::vector<TriId> marked_;
  std::vector<Side> ring_, ring2_;
  std::vector<Vec2> pts_;
  std::vector<double> h_;
  std::vector<std::uint32_t> moved_;
  std::vector<std::uint8_t> dirty_;        // per vertex: in dirty_list_
  std::vector<std::uint32_t> dirty_list_;  // vertices whose ball changed
  std::vector<std::uint32_t> work_;
  std::vector<std::uint8_t> side_queued_;  // per side: on stack_
  std::vector<Side> stack_;
};

void Adapter::evaluate(const std::vector<std::uint32_t>& verts) {
  pts_.resize(verts.size());
  h_.resize(verts.size());
  for (std::size_t i = 0; i < verts.size(); ++i) pts_[i] = m_.xy[verts[i]];
  if (opt_.size_at) opt_.size_at(pts_, h_);
  else std::fill(h_.begin(), h_.end(), opt_.size);
  res_.stats.size_evaluations += verts.size();
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const double h = h_[i];
    if (!(h > 0) || !std::isfinite(h)) {
      if (res_.error.empty())
        res_.error = "mesh size must be positive and finite (got " + std::to_string(h) + " at (" +
                     std::to_string(pts_[i].x) + ", " + std::to_string(pts_[i].y) + "))";
      return;
    }
    inv_h_[verts[i]] = 1 / h;
  }
}

void Adapter::evaluate_from(std::uint32_t first) {
  inv_h_.resize(m_.num_vertices(), 0);
  moved_.clear();
  for (std::uint32_t v = first; v < m_.num_vertices(); ++v) moved_.push_back(v);
  // In chunks, so a field sees batches of a bounded size.
  std::vector<std::uint32_t> chunk;
  for (std::size_t i = 0; i < moved_.size() && res_.error.empty(); i += 4096) {
    chunk.assign(moved_.begin() + i, moved_.begin() + std::min(moved_.size(), i + 4096));
    evaluate(chunk);
  }
}

void Adapter::mark(TriId t) {
  if (!t.valid() || (m_.tri_flags[t.value] & kMark)) return;
  m_.tri_flags[t.value] |= kMark;
  marked_.push_back(t);
}

void Adapter::mark_ball(VertexId v) {
  vertex_ring(m_, v, ring2_);
  dirty_.resize(m_.num_vertices(), 0);
  touch(v);
  for (Side x : ring2_) mark(tri_of(x)), touch(m_.dest(x)), touch(m_.apex(x));
}

void Adapter::clear_marks() {
  for (TriId t : marked_) m_.tri_flags[t.value] &= static_cast<std::uint8_t>(~kMark);
  marked_.clear();
}

std::uint64_t Adapter::split_pass() {
  cand_.clear();
  for (std::uint32_t s = 0; s < m_.corner.size(); ++s) {
    if (!m_.alive(tri_of(Side{s}))) continue;
    const Side o = m_.twin[s];
    if (o.valid() && o.value < s) continue;
    if (m_.constrained(Side{s}) && !opt_.split_constrained) continue;
    const double l = length(m_.corner[s], m_.dest(Side{s}));
    if (l > kLongEdge) cand_.push_back(std::uint64_t{std::bit_cast<std::uint32_t>(static_cast<float>(l))} << 32 | ~s);
  }
  std::sort(cand_.begin(), cand_.end(), std::greater<>());  // longest first, then smaller side id
  const std::uint32_t first_new = m_.num_vertices();
  std::uint64_t n = 0;
  for (std::uint64_t c : cand_) {
    if (m_.num_vertices() >= opt_.max_vertices) {
      res_.error = "meshadapt stopped at the vertex limit (" + std::to_string(opt_.max_vertices) + ")";
      break;
    }
    const Side s{~static_cast<std::uint32_t>(c)};
    const Side o = m_.twin[s.value];
    if ((m_.tri_flags[tri_of(s).value] & (kMark | kDead)) || (o.valid() && (m_.tri_flags[tri_of(o).value] & kMark)))
      continue;
    const bool on_boundary = m_.constrained(s) || !o.valid();
    const VertexId v = split_edge(m_, s, 0.5 * (m_.pos(m_.org(s)) + m_.pos(m_.dest(s))), opt_.split_constrained, pst());
    if (!v.valid()) continue;
    ++n;
    fixed_.push_back(on_boundary);
    mark_ball(v);
  }
  clear_marks();
  evaluate_from(first_new);
  res_.stats.splits += n;
  return n;
}

double Adapter::ball_min_rho(const std::vector<Side>& ring, Vec2 p) const {
  double q = 1;
  for (Side x : ring) q = std::min(q, rho(p, m_.pos(m_.dest(x)), m_.pos(m_.apex(x))));
  return q;
}

double Adapter::collapse_quality(VertexId w) const {
  const Vec2 pw = m_.pos(w);
  double q = 1;
  for (Side x : ring_) {
    const VertexId a = m_.dest(x), b = m_.apex(x);
    if (a == w || b == w) continue;
    if (length(w, a) > kLongEdge) return -1;
    q = std::min(q, rho(pw, m_.pos(a), m_.pos(b)));
  }
  return q;
}

std::uint64_t Adapter::collapse_pass() {
  cand_.clear();
  for (std::uint32_t s = 0; s < m_.corner.size(); ++s) {
    if (!m_.alive(tri_of(Side{s}))) continue;
    const Side o = m_.twin[s];
    if (!o.valid() || o.value < s || m_.constrained(Side{s})) continue;
    const VertexId a = m_.corner[s], b = m_.dest(Side{s});
    if (fixed_[a.value] && fixed_[b.value]) continue;
    const double l = length(a, b);
    if (l < kShortEdge) cand_.push_back(std::uint64_t{std::bit_cast<std::uint32_t>(static_cast<float>(l))} << 32 | s);
  }
  std::sort(cand_.begin(), cand_.end());  // shortest first, then smaller side id
  std::uint64_t n = 0;
  for (std::uint64_t c : cand_) {
    const Side s{static_cast<std::uint32_t>(c)};
    if (m_.tri_flags[tri_of(s).value] & (kMark | kDead)) continue;
    const Side o = m_.twin[s.value];
    if (!o.valid() || (m_.tri_flags[tri_of(o).value] & kMark)) continue;
    // Remove whichever free end leaves the better ball.
    Side best;
    double best_q = -1;
    for (Side e : {s, o}) {
      const VertexId v = m_.org(e);
      if (fixed_[v.value]) continue;
      if (can_collapse(m_, e, ring_, pst()) != CollapseCheck::Ok) continue;
      const double q_old = ball_min_rho(ring_, m_.pos(v));
      const double q = collapse_quality(m_.dest(e));
      // A collapse may lower the ball's worst quality only down to 0.3.
      if (q < 0 || q < std::min(q_old, 0.3)) continue;
      if (q > best_q) best_q = q, best = e;
    }
    if (!best.valid()) {
      ++res_.stats.collapses_refused;
      continue;
    }
    const VertexId w = m_.dest(best);
    vertex_ring(m_, m_.org(best), ring_);
    collapse_edge(m_, best, ring_);
    ++n;
    mark_ball(w);
  }
  clear_marks();
  res_.stats.collapses += n;
  return n;
}

std::uint64_t Adapter::swap_pass(bool all) {
  side_queued_.resize(m_.corner.size(), 0);
  const auto push = [&](Side x) {
    const Side y = m_.twin[x.value];
    if (!y.valid() || m_.constrained(x)) return;
    const Side key = x.value < y.value ? x : y;
    if (!side_queued_[key.value]) side_queued_[key.value] = 1, stack_.push_back(key);
  };
  stack_.clear();
  if (all) {
    for (auto s = static_cast<std::uint32_t>(m_.corner.size()); s-- > 0;)
      if (m_.alive(tri_of(Side{s}))) push(Side{s});
  } else {
    std::sort(dirty_list_.begin(), dirty_list_.end());
    for (std::size_t i = dirty_list_.size(); i-- > 0;) {
      if (!m_.out_side[dirty_list_[i]].valid()) continue;
      vertex_ring(m_, VertexId{dirty_list_[i]}, ring_);
      for (Side x : ring_) push(x), push(next(x)), push(prev(x));
    }
  }
  std::uint64_t n = 0;
  while (!stack_.empty()) {
    const Side s = stack_.back();
    stack_.pop_back();
    side_queued_[s.value] = 0;
    if (!(swap_gain(m_, s, pst()) > 1e-6)) continue;
    const Side e = m_.flip(s);  // d -> c
    ++n;
    const Side o = m_.twin[e.value];
    touch(m_.org(e)), touch(m_.dest(e)), touch(m_.apex(e)), touch(m_.apex(o));
    push(next(e)), push(prev(e)), push(next(o)), push(prev(o));
  }
  res_.stats.swaps += n;
  return n;
}

std::uint64_t Adapter::smooth_pass(bool all) {
  // Gauss-Seidel Laplacian: each free vertex moves to the mean of its
  // neighbours when its ball stays counter-clockwise (exact orient2d) and
  // its worst rho does not drop.
  work_.clear();
  if (all) {
    for (std::uint32_t v = 0; v < m_.num_vertices(); ++v) work_.push_back(v);
  } else {
    work_.swap(dirty_list_);
    std::sort(work_.begin(), work_.end());
  }
  for (std::uint32_t v : dirty_list_) dirty_[v] = 0;
  dirty_list_.clear();
  for (std::uint32_t v : work_) dirty_[v] = 0;
  moved_.clear();
  for (std::uint32_t v : work_) {
    if (fixed_[v] || !m_.out_side[v].valid()) continue;
    if (vertex_ring(m_, VertexId{v}, ring_) != FanEnd::Closed) continue;
    Vec2 sum{0, 0};
    for (Side x : ring_) sum += m_.pos(m_.dest(x));
    const Vec2 p = sum / static_cast<double>(ring_.size());
    const Vec2 old = m_.xy[v];
    bool ok = true;
    for (Side x : ring_)
      if (orient2d(p, m_.pos(m_.dest(x)), m_.pos(m_.apex(x)), pst()) != Sign::Positive) {
        ok = false;
        break;
      }
    if (!ok || ball_min_rho(ring_, p) < ball_min_rho(ring_, old)) continue;
    m_.xy[v] = p;
    moved_.push_back(v);
    if (norm2(p - old) * inv_h_[v] * inv_h_[v] > 1e-4) {
      touch(VertexId{v});
      for (Side x : ring_) touch(m_.dest(x));
    }
  }
  res_.stats.smoothed += moved_.size();
  std::vector<std::uint32_t> moved;
  moved.swap(moved_);
  for (std::size_t i = 0; i < moved.size() && res_.error.empty(); i += 4096) {
    std::vector<std::uint32_t> chunk(moved.begin() + i, moved.begin() + std::min(moved.size(), i + 4096));
    evaluate(chunk);
  }
  return moved.size();
}

void Adapter::run() {
  const std::uint32_t n_input = m_.num_vertices();
  fixed_.assign(n_input, 1);
  if (opt_.move_input_vertices) {
    std::fill(fixed_.begin(), fixed_.end(), 0);
    for (std::uint32_t s = 0; s < m_.corner.size(); ++s) {
      if (!m_.alive(tri_of(Side{s}))) continue;
      if (m_.constrained(Side{s}) || !m_.twin[s].valid())
        fixed_[m_.corner[s].value] = fixed_[m_.dest(Side{s}).value] = 1;
    }
    for (std::uint32_t v = 0; v < n_input; ++v) fixed_[v] |= !m_.out_side[v].valid();
  }
  evaluate_from(0);
  dirty_.assign(n_input, 0);
  std::uint64_t fewest = ~0ull;
  int stalled = 0;
  for (int it = 0; it < opt_.max_iterations && res_.error.empty(); ++it) {
    ++res_.stats.iterations;
    const std::uint64_t split = split_pass();
    after("split");
    if (!res_.error.empty()) break;
    const std::uint64_t collapsed = collapse_pass();
    after("collapse");
    swap_pass(it == 0);
    after("swap");
    for (int k = 0; k < opt_.smoothing_passes && res_.error.empty(); ++k) smooth_pass(false), after("smooth");
    if (split == 0 && collapsed == 0) break;
    // Stall detection starts once a round changes less than 1% of the
    // triangles (the refinement front has swept the domain).
    const std::uint64_t changes = split + collapsed;
    if (changes * 100 > m_.num_triangles()) continue;
    if (changes < fewest) fewest = changes, stalled = 0;
    else if (++stalled >= kStallRounds) break;
  }
  if (!res_.error.empty()) return;
  // A full swap pass, then full smoothing sweeps each followed by swaps.
  swap_pass(true);
  after("swap");
  for (int k = 0; k < opt_.smoothing_passes && res_.error.empty(); ++k) {
    smooth_pass(true);
    after("smooth");
    swap_pass(false);
    after("swap");
  }
  res_.vertex_map = drop_isolated_vertices(m_, opt_.move_input_vertices ? 0 : n_input);
}

}  // namespace

MeshAdaptResult mesh_adapt(TriangleStore& m, const MeshAdaptOptions& opt) {
  MeshAdaptResult res;
  if (!opt.size_at && !(opt.size > 0 && std::isfinite(opt.size))) {
    res.error = "meshadapt needs a positive finite size (got " + std::to_string(opt.size) + ")";
    return res;
  }
  Adapter a(m, opt, res);
  a.run();
  return res;
}

}  // namespace sm
