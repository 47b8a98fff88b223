// Quality optimisation after refinement: swaps and star optimisation of the vertices of
// the worst triangles, on the flat store, with a worklist that stays local to them.
#include "mesh/modify/optimize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/parallel.h"
#include "exact/predicates.h"
#include "exact/quality.h"
#include "mesh/modify/flip_valence.h"
#include "mesh/modify/optimize_blocks.h"

namespace sm {
namespace {

constexpr double kHalfSqrt3 = 0.8660254037844386;
// Triangles per chunk of the scans over the whole store: fixed, so the chunks do not
// depend on the thread count.
constexpr std::size_t kOptimizeScanChunk = 16384;
// The statistics' "good" bar: no swap or move may lower the number of triangles above it.
constexpr double kGood = 0.9;
// A swap or move that pushes `lost` triangles below kGood is kept only when the worst rho
// it starts from is below OptimizeOptions::sacrifice_below, rises by at least kTrade per
// lost triangle (lifting a bad triangle is worth a few good ones dropping a little, a
// mediocre one is not), and earlier changes gained as many (Optimizer::bank_).
constexpr double kTrade = 0.02;

// The point p that makes (p, b, c) equilateral and counter-clockwise: on the left of b -> c.
inline Vec2 ideal_apex(Vec2 b, Vec2 c) {
  const Vec2 d = c - b;
  return 0.5 * (b + c) + kHalfSqrt3 * Vec2{-d.y, d.x};
}

// An outer edge (b, c) of a vertex star: the triangle (centre, b, c) is counter-clockwise.
struct StarEdge {
  Vec2 b, c;
  Vec3 sb, sc;  // on the surface, with OptimizeOptions::to_space
  double length = 0;  // norm(sb - sc): the same for every position of the centre
  double plane_length = 0;  // std::sqrt(norm2(b - c)): rho_terms_ccw's la (optimise_position)
};

// Sorted qualities compared worst first: the first pair that differs by more than
// kLexTie decides. A move that lifts a triangle pinned by the boundary (a needle on a
// short coast edge) by a hair must not pull its other triangles down to that needle.
constexpr double kLexTie = 1e-3;
inline bool leximin_better(const std::vector<double>& a, const std::vector<double>& b) {
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (a[i] > b[i] + kLexTie) return true;
    if (a[i] < b[i] - kLexTie) return false;
  }
  return false;
}

class Optimizer {
 public:
  Optimizer(TriangleStore& m, std::uint32_t fixed_count, const OptimizeOptions& opt)
      : m_(m), fixed_count_(fixed_count), opt_(opt), space_(static_cast<bool>(opt.to_space)) {
    if (space_) xyz_.resize(m.num_vertices()), have_xyz_.assign(m.num_vertices(), 0);
    tri_mark_.assign(m.num_slots(), 0);
    changed_.assign(m.num_vertices(), 0);
    vert_stamp_.assign(m.num_vertices(), 0);
    stuck_.assign(m.num_vertices(), 0);
  }

  OptimizeStats run() {
    OptimizeStats st;
    const double min_all = scan_bad();
    std::sort(bad_.begin(), bad_.end());
    bank_ = static_cast<std::int64_t>(std::max(0.0, opt_.max_share_loss) * m_.num_triangles());
    st.min_before = m_.num_triangles() ? min_all : 0;
    st.bad_before = static_cast<std::uint32_t>(bad_.size());
    for (int r = 0; r < opt_.rounds && !bad_.empty(); ++r) {
      ++st.rounds;
      const std::uint64_t swaps0 = st.swaps, moves0 = st.moves;
      const std::size_t bad0 = bad_.size();
      swap_round(st);
      refresh_bad();
      smooth_round(st);
      refresh_bad();
      if (st.swaps == swaps0 && st.moves == moves0) break;
      if (small_gain(bad0)) break;
    }
    for (int r = 0; r < opt_.rounds && !bad_.empty() && bad_.front().q < opt_.compound_below; ++r) {
      const std::uint64_t swaps0 = st.swaps;
      const std::size_t bad0 = bad_.size();
      compound_round(st);
      refresh_bad();
      smooth_round(st);
      refresh_bad();
      if (st.swaps == swaps0) break;
      if (small_gain(bad0)) break;
    }
    st.bad_after = static_cast<std::uint32_t>(bad_.size());
    if (!bad_.empty()) {
      st.min_after = std::max(bad_.front().q, 0.0);
    } else {
      // Every triangle is at or above the threshold: one scan for the exact minimum.
      const double mn = scan_bad();
      st.min_after = m_.num_triangles() ? mn : 0;
    }
    return st;
  }

 private:
  Vec3 xyz(VertexId v) {
    if (!have_xyz_[v.value]) xyz_[v.value] = opt_.to_space(m_.pos(v)), have_xyz_[v.value] = 1;
    return xyz_[v.value];
  }

  double quality(VertexId a, VertexId b, VertexId c) {
    const double q = rho_ccw(m_.pos(a), m_.pos(b), m_.pos(c));
    if (!space_ || q < 0) return q;
    return rho(xyz(a), xyz(b), xyz(c));
  }
  double tri_quality(TriId t) { return quality(m_.vertex(t, 0), m_.vertex(t, 1), m_.vertex(t, 2)); }

  // Every live triangle measured: those below the threshold appended to bad_ by slot, and
  // the lowest rho (flat ones as 0) returned. Without to_space (whose cache is not shared
  // between threads) the triangles are measured in fixed chunks on the threads, the lists
  // joined in chunk order: the serial scan's list and minimum.
  double scan_bad() {
    const std::size_t n = m_.num_slots();
    if (space_ || opt_.threads <= 1 || n <= kOptimizeScanChunk) {
      double min_all = 1;
      for (std::uint32_t t = 0; t < n; ++t) {
        if (!m_.alive(TriId{t})) continue;
        const double q = tri_quality(TriId{t});
        min_all = std::min(min_all, std::max(q, 0.0));  // -1: flat in floating point
        if (q < opt_.threshold && seeded(t)) bad_.push_back({q, t});
      }
      return min_all;
    }
    return scan_plane_bad(m_, opt_.threshold, opt_.threads, opt_.seeds, bad_);
  }

  // Whether the round that started with bad0 triangles below the threshold lifted fewer
  // than min_round_gain of them (counted as the fall of the bad list, which also holds the
  // triangles the round pushed below).
  bool small_gain(std::size_t bad0) const {
    const double lifted = static_cast<double>(bad0) - static_cast<double>(bad_.size());
    return lifted < opt_.min_round_gain * static_cast<double>(bad0);
  }

  bool seeded(std::uint32_t t) const { return !opt_.seeds || (*opt_.seeds)[t]; }

  // Whether a change that raises the worst rho from `before` by `gain` may push `lost`
  // triangles below kGood (`lost_total` since the change began).
  bool fair_trade(double gain, int lost, double before, int lost_total) {
    if (lost <= 0 && lost_total <= 0) return true;
    if (strict_) return false;
    if (lost > 0 && (!(before < opt_.sacrifice_below) || gain < kTrade * lost)) return false;
    if (lost_total <= bank_) return true;
    bank_blocked_ = true;
    return false;
  }

  // Triangle t is to be measured again by refresh_bad.
  void mark(std::uint32_t t) {
    if (!tri_mark_[t]) tri_mark_[t] = 1, touched_.push_back(t);
  }
  // Triangle t changed (flip, a corner moved): measured again, corners smoothed again, and
  // their stars changed now (every change of a star, or of a position in it, touches a
  // triangle of the star: a move touches the mover's star, a flip its two new triangles).
  void touch(std::uint32_t t) {
    ++clock_;
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t v = m_.vertex(TriId{t}, e).value;
      stuck_[v] = 0;
      changed_[v] = clock_;
    }
    mark(t);
  }

  // bad_ := the triangles of bad_ and touched_ below the threshold, re-measured, sorted.
  void refresh_bad() {
    for (const BadTri& b : bad_) mark(b.t);
    bad_.clear();
    for (std::uint32_t t : touched_) {
      tri_mark_[t] = 0;
      const double q = tri_quality(TriId{t});
      if (q < opt_.threshold) bad_.push_back({q, t});
    }
    touched_.clear();
    std::sort(bad_.begin(), bad_.end());
  }

  // Flips s when the worse rho of its two triangles rises; the new pair must be
  // counter-clockwise by the exact orient2d.
  bool try_swap(Side s) {
    const Side o = m_.twin[s.value];
    if (!o.valid() || m_.constrained(s)) return false;
    const VertexId a = m_.org(s), b = m_.dest(s), c = m_.apex(s), d = m_.apex(o);
    const double q1 = quality(a, b, c), q2 = quality(b, a, d), q3 = quality(c, a, d), q4 = quality(d, b, c);
    if (!(std::min(q3, q4) > std::min(q1, q2) + opt_.min_gain)) return false;
    const int lost = (q1 > kGood) + (q2 > kGood) - (q3 > kGood) - (q4 > kGood);
    if (!fair_trade(std::min(q3, q4) - std::min(q1, q2), lost, std::min(q1, q2), lost)) return false;
    if (orient2d(m_.pos(c), m_.pos(a), m_.pos(d)) != Sign::Positive ||
        orient2d(m_.pos(d), m_.pos(b), m_.pos(c)) != Sign::Positive)
      return false;
    const Side n = m_.flip(s);
    bank_ -= lost;
    touch(tri_of(n).value);
    touch(tri_of(m_.twin[n.value]).value);
    const Side outer[4] = {next(n), prev(n), next(m_.twin[n.value]), prev(m_.twin[n.value])};
    for (Side x : outer)
      if (m_.twin[x.value].valid() && !m_.constrained(x)) stack_.push_back(x);
    return true;
  }

  void swap_round(OptimizeStats& st) {
    // Worst first: the edges of each bad triangle, then the cascade its flips start.
    for (const BadTri& b : bad_) {
      for (std::uint32_t e = 0; e < 3; ++e) stack_.push_back(side_of(TriId{b.t}, e));
      while (!stack_.empty()) {
        const Side s = stack_.back();
        stack_.pop_back();
        st.swaps += try_swap(s);
      }
    }
  }

  // The star of v as its outer edges (b, c), counter-clockwise triangles (v, b, c);
  // false when v must not move (pinned, on a constrained or hull edge, isolated).
  bool gather_star(VertexId v) {
    star_.clear();
    star_tris_.clear();
    fail_first_ = SIZE_MAX;
    if (v.value < fixed_count_ || !m_.out_side_ok(v)) return false;
    // A star on a constrained edge or the hull is not free; a corrupt fan is left alone.
    const FanEnd end = for_each_fan_side(m_, m_.out_side[v.value], [this](Side s) {
      if (m_.constrained(s)) return false;
      add_star_edge(m_.dest(s), m_.apex(s));
      star_tris_.push_back(tri_of(s).value);
      return true;
    });
    return end == FanEnd::Closed && star_.size() >= 3;
  }

  void add_star_edge(VertexId b, VertexId c) {
    StarEdge e{m_.pos(b), m_.pos(c), {}, {}, 0, 0};
    if (space_) e.sb = xyz(b), e.sc = xyz(c), e.length = norm(e.sb - e.sc);
    star_.push_back(e);
  }

  // The worst rho of the star with its centre at p; -1 as soon as a triangle is not
  // counter-clockwise (floating point) or not above `floor`. *good counts the
  // triangles above kGood, *worst names the worst.
  double star_quality(Vec2 p, double floor, int* good, std::size_t* worst = nullptr,
                      std::vector<double>* sorted = nullptr) {
    double mn = 2;
    *good = 0;
    if (sorted) sorted->clear();
    Vec3 ps{};
    if (space_) ps = opt_.to_space(p);
    // The rho of the triangle on e with its centre at p, or -1 when that triangle is not
    // counter-clockwise or not above the floor.
    const auto measure = [&](const StarEdge& e) -> double {
      if (space_) {
        if (!(cross(e.b - p, e.c - p) > 0)) return -1;
        const double q = rho(ps, e.sb, e.sc, e.length);
        return q > floor ? q : -1;
      }
      // rho = num / den; the early exit compares without the division.
      const RhoTerms r = rho_terms_ccw(p, e.b, e.c, e.plane_length);
      if (!(r.area2 > 0) || !(r.num > floor * r.den)) return -1;
      return r.num / r.den;
    };
    // The triangle that failed last is measured first: along a line search the same one
    // fails step after step. Whichever fails, the answer is -1 (the counts, partial then,
    // are not read), so the order changes nothing else.
    std::size_t tried = star_.size();
    double tried_q = 0;
    if (fail_first_ < star_.size()) {
      tried_q = measure(star_[fail_first_]);
      if (tried_q < 0) return -1;
      tried = fail_first_;
    }
    for (std::size_t i = 0; i < star_.size(); ++i) {
      const double q = i == tried ? tried_q : measure(star_[i]);
      if (q < 0) {
        fail_first_ = i;
        return -1;
      }
      *good += q > kGood;
      if (sorted) sorted->push_back(q);
      if (q < mn) {
        mn = q;
        if (worst) *worst = i;
      }
    }
    if (sorted) std::sort(sorted->begin(), sorted->end());
    return mn;
  }

  bool exact_ok(Vec2 p) const {
    for (const StarEdge& e : star_)
      if (orient2d(p, e.b, e.c) != Sign::Positive) return false;
    return true;
  }

  // From `start`, where the star (star_) has worst rho `best` and `good` triangles above
  // kGood, a few line searches towards the candidates of optimize.h; returns the
  // position reached (start when nothing was better) and updates best. Every step is
  // checked with the exact orient2d.
  Vec2 optimise_position(Vec2 start, double& best, int& good, OptimizeStats& st, int* good_start = nullptr) {
    Vec2 cur = start;
    std::size_t worst = 0;
    // The plane lengths of the outer edges once per search, not once per candidate (the
    // stars gathered only for their triangles, region_quality's, need none).
    if (!space_)
      for (StarEdge& e : star_) e.plane_length = std::sqrt(norm2(e.b - e.c));
    best = star_quality(cur, -2, &good, &worst, &cur_q_);
    if (best < 0) return start;  // tangled in floating point already: not ours to fix
    const int good0 = good;
    if (good_start) *good_start = good0;
    Vec2 lap{0, 0}, ideal{0, 0};
    for (const StarEdge& e : star_) {
      lap += e.b;
      ideal += ideal_apex(e.b, e.c);
    }
    const double k = 1.0 / static_cast<double>(star_.size());
    lap *= k, ideal *= k;
    for (int it = 0; it < opt_.smooth_iterations; ++it) {
      const Vec2 targets[3] = {ideal, ideal_apex(star_[worst].b, star_[worst].c), lap};
      // The worst may not drop at all: a candidate is measured only while above this.
      const double floor = std::nextafter(best, -2.0);
      Vec2 best_p = cur;
      best_q_ = cur_q_;
      // The chosen candidate's worst rho, count above kGood and worst triangle: measured
      // in full (nothing below the floor), so the same as measuring the star there again.
      double chosen = best;
      int chosen_good = good;
      std::size_t chosen_worst = worst;
      for (const Vec2 target : targets) {
        for (double step = 1; step >= 1.0 / 128; step *= 0.5) {
          const Vec2 p = cur + step * (target - cur);
          // A candidate on the current position (the target reached by the last move, a
          // step too small to move in floating point) measures cur_q_ again: never
          // leximin-better, no triangle below the floor, so nothing to learn. After a move
          // to the mean of the ideal points, the next search's first target is cur itself.
          if (p == cur && !opt_.remeasure_current) continue;
          ++st.star_measures;
          int g = 0;
          std::size_t w = 0;
          // The sorted qualities must rise (leximin).
          const double q = star_quality(p, floor, &g, &w, &cand_q_);
          if (q >= best && leximin_better(cand_q_, cur_q_) && fair_trade(q - best, good - g, best, good0 - g)) {
            if (leximin_better(cand_q_, best_q_))
              best_q_ = cand_q_, best_p = p, chosen = q, chosen_good = g, chosen_worst = w;
            break;
          }
        }
      }
      if (best_p == cur) break;
      if (!exact_ok(best_p)) {
        ++st.refused;
        break;
      }
      cur = best_p;
      best = chosen, good = chosen_good, worst = chosen_worst;
      cur_q_.swap(best_q_);
    }
    return cur;
  }

  // Moves v to raise the worst rho of its star; true when it moved.
  bool smooth_vertex(VertexId v, OptimizeStats& st) {
    // A vertex that found no better place keeps it until something around it changes.
    if (stuck_[v.value]) return false;
    stuck_[v.value] = 1;
    if (!gather_star(v)) return false;
    const Vec2 start = m_.pos(v);
    double best = 0;
    int good = 0;
    int good0 = 0;  // the star's count above kGood where it starts (read only when it moved)
    bank_blocked_ = false;
    const Vec2 cur = optimise_position(start, best, good, st, &good0);
    // Refused only for want of gained triangles: worth another try in a later round.
    if (bank_blocked_) stuck_[v.value] = 0;
    if (cur == start) return false;
    bank_ += good - good0;
    m_.will_change_vertex(v);
    m_.xy[v.value] = cur;
    if (space_) xyz_[v.value] = opt_.to_space(cur), have_xyz_[v.value] = 1;
    for (std::uint32_t t : star_tris_) touch(t);
    return true;
  }

  // The worst rho and the number above kGood of t1, t2 and the stars of the free
  // vertices among vs; region_ lists those triangles.
  std::pair<double, int> region_quality(const std::array<VertexId, 4>& vs, std::uint32_t t1, std::uint32_t t2,
                                        std::vector<double>& sorted) {
    region_.assign({t1, t2});
    for (VertexId v : vs)
      if (gather_star(v))
        for (std::uint32_t t : star_tris_)
          if (std::find(region_.begin(), region_.end(), t) == region_.end()) region_.push_back(t);
    double mn = 2;
    int good = 0;
    sorted.clear();
    for (std::uint32_t t : region_) {
      const double q = tri_quality(TriId{t});
      mn = std::min(mn, q);
      good += q > kGood;
      sorted.push_back(q);
    }
    std::sort(sorted.begin(), sorted.end());
    return {mn, good};
  }

  // Whether triangle t (its corners among vs) keeps every corner fixed through a compound
  // change's sweeps and has a rho below q: region_quality then measures it again in the
  // same slot, corners in the same order (the same double), so the change's worst rho
  // stays below q whatever the sweeps do. Round a dam or a coast edge much shorter than
  // its neighbours most quads are so (docs/benchmarks.md: the deviation bound's extra
  // closures); deciding it before the sweeps leaves only the failure's traces to make.
  bool pinned_below(std::uint32_t t, const std::array<VertexId, 4>& vs, const std::array<bool, 4>& free, double q) {
    for (std::uint32_t e = 0; e < 3; ++e)
      for (std::size_t i = 0; i < 4; ++i)
        if (free[i] && m_.vertex(TriId{t}, e) == vs[i]) return false;
    return tri_quality(TriId{t}) < q;
  }

  // Flips s even when that alone does not help, then moves the four corners of the quad
  // (two sweeps, no sacrifice); kept only when the worst rho round them rises and no
  // triangle drops below kGood, otherwise undone exactly (positions, then the flip back).
  // Escapes the local optima of single moves where a vertex has one neighbour too many.
  // A change that pinned_below shows to fail, or that failed before with nothing round it
  // changed since, makes only the failure's traces (the flip, the positions written back,
  // the flip back that exchanges the two slots, the marks).
  bool try_compound(Side s, OptimizeStats& st) {
    const Side o = m_.twin[s.value];
    if (!o.valid() || m_.constrained(s)) return false;
    if (flip_valence_rise(m_, s, fixed_count_) > opt_.compound_valence_rise) {
      ++st.compound_valence_skipped;
      return false;
    }
    const std::array<VertexId, 4> vs = {m_.org(s), m_.dest(s), m_.apex(s), m_.apex(o)};
    if (orient2d(m_.pos(vs[2]), m_.pos(vs[0]), m_.pos(vs[3])) != Sign::Positive ||
        orient2d(m_.pos(vs[3]), m_.pos(vs[1]), m_.pos(vs[2])) != Sign::Positive)
      return false;
    // The change reads the quad and the stars of its free corners only (a fixed corner
    // never moves, and its triangles outside the quad and those stars are not in the
    // region); it failed on this edge with the same four corners in the same roles
    // before, and none of the free corners' stars changed since: it fails again. The
    // fixed corners' stars are not asked: a coast point beside a dam or a short coast edge
    // has a wide star, touched by every change round it, and the quads at it would
    // otherwise be worked out again after each (docs/benchmarks.md, the deviation bound).
    const std::uint64_t key = (std::uint64_t{vs[0].value} << 32) | vs[1].value;
    const auto known = failed_.find(key);
    const bool repeat = known != failed_.end() && unchanged_since(known->second, vs);
    double q0 = 0;
    int g0 = 0;
    if (!repeat) std::tie(q0, g0) = region_quality(vs, tri_of(s).value, tri_of(o).value, region_q0_);
    std::array<Vec2, 4> old_xy;
    for (std::size_t i = 0; i < 4; ++i) old_xy[i] = m_.pos(vs[i]);
    const Side n = m_.flip(s);
    // Only the corners free after the flip move (whether a vertex is free depends on the
    // edges round it, which the sweeps do not change).
    std::array<bool, 4> free{};
    if (repeat)
      free = known->second.free;
    else
      for (std::size_t i = 0; i < 4; ++i) free[i] = gather_star(vs[i]);
    ++st.compound_tried;
    if (repeat) {
      ++st.compound_repeated;
    } else if (pinned_below(tri_of(n).value, vs, free, q0) ||
               pinned_below(tri_of(m_.twin[n.value]).value, vs, free, q0)) {
      ++st.compound_pinned;
    } else {
      strict_ = true;
      for (int sweep = 0; sweep < 2; ++sweep)
        for (std::size_t i = 0; i < 4; ++i) {
          const VertexId v = vs[i];
          if (!free[i] || !gather_star(v)) continue;
          double best = 0;
          int good = 0;
          const Vec2 p = optimise_position(m_.pos(v), best, good, st);
          m_.will_change_vertex(v);
          m_.xy[v.value] = p;
          if (space_) xyz_[v.value] = opt_.to_space(p), have_xyz_[v.value] = 1;
        }
      strict_ = false;
      const auto [q1, g1] = region_quality(vs, tri_of(n).value, tri_of(m_.twin[n.value]).value, region_q1_);
      if (q1 >= q0 && leximin_better(region_q1_, region_q0_) && g1 >= g0) {
        for (std::uint32_t t : region_) touch(t);
        ++st.swaps;
        for (std::size_t i = 0; i < 4; ++i) st.moves += !(m_.pos(vs[i]) == old_xy[i]);
        return true;
      }
    }
    for (std::size_t i = 0; i < 4; ++i) {
      m_.will_change_vertex(vs[i]);
      m_.xy[vs[i].value] = old_xy[i];
      if (space_) xyz_[vs[i].value] = opt_.to_space(old_xy[i]), have_xyz_[vs[i].value] = 1;
    }
    failed_[key] = FailedChange{clock_, vs[2], vs[3], free};
    // The flip back restores the two triangles with their slots exchanged: measure both again.
    const Side back = m_.flip(n);
    mark(tri_of(back).value);
    mark(tri_of(m_.twin[back.value]).value);
    return false;
  }

  // A compound change that failed: the clock_ then, the quad's other two corners (the
  // edge's org and dest are the key) and which of the four corners were free.
  struct FailedChange {
    std::uint64_t clock = 0;
    VertexId apex, twin_apex;
    std::array<bool, 4> free{};
  };

  // Whether the change on the quad vs is the one that failed as f with nothing it reads
  // changed since: the same corners, no free corner's star changed after the failure, and
  // neither of the quad's triangles made again (a triangle of fixed corners only is in no
  // free corner's star: its corners' stars are asked then). Whether a corner is free
  // depends only on the edges round it (constrained ones are never flipped) and
  // fixed_count_, so the same corners are free now.
  bool unchanged_since(const FailedChange& f, const std::array<VertexId, 4>& vs) const {
    if (f.apex != vs[2] || f.twin_apex != vs[3]) return false;
    const bool pinned_left = !f.free[0] && !f.free[1] && !f.free[2];    // (org, dest, apex)
    const bool pinned_right = !f.free[0] && !f.free[1] && !f.free[3];   // (dest, org, twin apex)
    for (std::size_t i = 0; i < 4; ++i) {
      const bool asked = f.free[i] || (pinned_left && i != 3) || (pinned_right && i != 2);
      if (asked && changed_[vs[i].value] > f.clock) return false;
    }
    return true;
  }

  void compound_round(OptimizeStats& st) {
    const std::vector<BadTri> bad = bad_;
    for (const BadTri& b : bad) {
      if (!(b.q < opt_.compound_below)) break;
      for (std::uint32_t e = 0; e < 3; ++e) {
        if (!(tri_quality(TriId{b.t}) < opt_.compound_below)) break;  // an earlier change lifted it
        if (try_compound(side_of(TriId{b.t}, e), st)) break;
      }
    }
  }

  void smooth_round(OptimizeStats& st) {
    ++stamp_;
    order_.clear();
    for (const BadTri& b : bad_)
      for (std::uint32_t e = 0; e < 3; ++e) {
        const VertexId v = m_.vertex(TriId{b.t}, e);
        if (vert_stamp_[v.value] != stamp_) vert_stamp_[v.value] = stamp_, order_.push_back(v);
      }
    // Vertex order rather than worst first: neighbours in the arrays are neighbours in
    // the mesh far more often, and the moves are local anyway.
    std::sort(order_.begin(), order_.end(), [](VertexId a, VertexId b) { return a.value < b.value; });
    for (VertexId v : order_) st.moves += smooth_vertex(v, st);
  }

  TriangleStore& m_;
  const std::uint32_t fixed_count_;
  const OptimizeOptions& opt_;
  const bool space_;
  std::vector<Vec3> xyz_;
  std::vector<std::uint8_t> have_xyz_;
  std::vector<BadTri> bad_;
  std::vector<std::uint32_t> touched_;
  std::vector<std::uint8_t> tri_mark_;
  std::vector<std::uint32_t> vert_stamp_;
  std::vector<std::uint8_t> stuck_;  // per vertex: smoothing found nothing, star unchanged since
  // Per vertex: the clock_ of the last change of its star (touch); per edge (org << 32 |
  // dest) whose compound change failed: that failure (FailedChange).
  std::vector<std::uint64_t> changed_;
  std::uint64_t clock_ = 0;
  std::unordered_map<std::uint64_t, FailedChange> failed_;
  std::uint32_t stamp_ = 0;
  // Triangles above kGood gained minus lost so far: never negative, so the share of
  // rho > 0.9 never falls below the input's.
  std::int64_t bank_ = 0;
  bool bank_blocked_ = false;  // a change was refused only because bank_ was short
  bool strict_ = false;        // no sacrifice at all (inside a compound change)
  std::vector<std::uint32_t> region_;
  std::vector<double> cur_q_, cand_q_, best_q_, region_q0_, region_q1_;
  std::vector<Side> stack_;
  std::vector<StarEdge> star_;
  std::size_t fail_first_ = SIZE_MAX;  // the star's triangle that last fell below the floor
  std::vector<std::uint32_t> star_tris_;
  std::vector<VertexId> order_;
};

}  // namespace

OptimizeStats optimize_quality(TriangleStore& m, std::uint32_t fixed_count, const OptimizeOptions& opt) {
  if (opt.block_min_triangles > 0 && m.num_triangles() >= opt.block_min_triangles && !opt.to_space &&
      !opt.seeds)
    return optimize_in_blocks(m, fixed_count, opt);
  return Optimizer(m, fixed_count, opt).run();
}

double scan_plane_bad(const TriangleStore& m, double threshold, int threads, const std::vector<std::uint8_t>* seeds,
                      std::vector<BadTri>& bad) {
  struct Chunk {
    std::vector<BadTri> bad;
    double min_all = 1;
  };
  const std::size_t n = m.num_slots();
  std::vector<Chunk> chunks((n + kOptimizeScanChunk - 1) / kOptimizeScanChunk);
  parallel_for_chunks(threads, n, kOptimizeScanChunk, [&](std::size_t begin, std::size_t end) {
    Chunk& c = chunks[begin / kOptimizeScanChunk];
    for (std::size_t slot = begin; slot < end; ++slot) {
      const TriId t{static_cast<std::uint32_t>(slot)};
      if (!m.alive(t)) continue;
      const double q = rho_ccw(m.pos(m.vertex(t, 0)), m.pos(m.vertex(t, 1)), m.pos(m.vertex(t, 2)));
      c.min_all = std::min(c.min_all, std::max(q, 0.0));
      if (q < threshold && (!seeds || (*seeds)[slot])) c.bad.push_back({q, t.value});
    }
  });
  double min_all = 1;
  for (const Chunk& c : chunks) {
    min_all = std::min(min_all, c.min_all);
    bad.insert(bad.end(), c.bad.begin(), c.bad.end());
  }
  return min_all;
}

}  // namespace sm
