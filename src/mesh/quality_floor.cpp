// The quality floor (quality_floor.h): rounds over the triangles below q, worst first.
#include "mesh/quality_floor.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "base/parallel.h"
#include "exact/predicates.h"
#include "exact/segments.h"
#include "exact/quality.h"
#include "mesh/insert.h"
#include "mesh/locate.h"
#include "mesh/modify/smooth.h"
#include "mesh/modify/split.h"
#include "mesh/quality.h"
#include "mesh/store_undo.h"

namespace sm {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Triangles (or vertices) per chunk of the floor's scans over the whole face: fixed, so
// the chunks, and the results reduced in chunk order, do not depend on the thread count.
constexpr std::size_t kFloorScanChunk = 16384;

// fn(begin, end) over the chunks of [0, n), on `threads` threads when there is more than
// one chunk (a single chunk, as after each insertion, runs here without the fork).
void floor_scan(int threads, std::size_t n, const std::function<void(std::size_t, std::size_t)>& fn) {
  if (n <= kFloorScanChunk) {
    if (n > 0) fn(0, n);
    return;
  }
  parallel_for_chunks(threads, n, kFloorScanChunk, fn);
}

std::size_t floor_scan_chunks(std::size_t n) { return (n + kFloorScanChunk - 1) / kFloorScanChunk; }

// rho of the isoceles triangle with apex angle a: 8 sin(a/2) sin^2((pi - a)/4).
double isoceles_rho(double a) {
  const double s = std::sin(0.25 * (kPi - a));
  return 8 * std::sin(0.5 * a) * s * s;
}

// The plane angle at corner e of triangle t (at its vertex e, between its two edges).
double corner_angle(const TriangleStore& m, TriId t, std::uint32_t e) {
  const Vec2 p = m.pos(m.vertex(t, e)), a = m.pos(m.vertex(t, (e + 1) % 3)), b = m.pos(m.vertex(t, (e + 2) % 3));
  return std::atan2(std::abs(cross(a - p, b - p)), dot(a - p, b - p));
}

// The angle of the domain at corner e of t: the sum of the plane angles at that vertex of
// the triangles of its wedge, the fan reached from t without crossing a constrained (or
// hull) edge.
// At most num_slots() steps each way (a fan holds each triangle once); *overrun when a
// corrupt fan does not end.
double wedge_angle(const TriangleStore& m, TriId t, std::uint32_t e, bool* overrun) {
  double sum = corner_angle(m, t, e);
  const VertexId v = m.vertex(t, e);
  // Around v one way across the side of t leaving v, the other way across the side
  // arriving at v. A closed fan (no constrained edge at v) comes back to t.
  for (int dir = 0; dir < 2; ++dir) {
    Side s = dir == 0 ? side_of(t, e) : side_of(t, (e + 2) % 3);
    for (std::uint32_t guard = 0;; ++guard) {
      if (guard > m.num_slots()) {
        *overrun = true;
        return sum;
      }
      if (m.constrained(s)) break;
      const Side o = m.twin[s.value];
      if (!o.valid()) break;
      const TriId u = tri_of(o);
      if (u == t) return 2 * kPi;
      std::uint32_t ev = 0;
      while (m.vertex(u, ev) != v) ++ev;
      sum += corner_angle(m, u, ev);
      // Entered across the side of u arriving at v (dir 0) or leaving it (dir 1): leave
      // across the other one.
      s = dir == 0 ? side_of(u, ev) : side_of(u, (ev + 2) % 3);
    }
  }
  return sum;
}

// Where a curve edge is split, as fractions of its curve parameter from its origin: the
// midpoint first, then points nearer the ends (split_curve_edge says why).
constexpr double kSplitFractions[] = {0.5, 0.25, 0.75};

class Floor {
 public:
  Floor(TriangleStore& m, const FloorFace& face, const QualityFloorOptions& opt)
      : m_(m), face_(face), q_(opt.floor), limit_(sharp_angle_limit(opt.floor)),
        never_below_start_(opt.never_below_start), threads_(std::max(1, opt.threads)), ins_(m) {}

  QualityFloorResult run(const QualityFloorOptions& opt);

 private:
  /// An internal error near v (a walk that did not end): the floor stops (stopped()).
  void fault(const char* what, VertexId v) {
    if (res_.fault.empty()) res_.fault = what, res_.fault_at = v;
  }
  bool stopped() const { return !res_.fault.empty() || work_ >= budget_; }
  /// One operation of the work budget spent; false when none is left (or after a fault).
  bool spend() {
    if (stopped()) return false;
    ++work_;
    return true;
  }
  double wedge(TriId t, std::uint32_t e) {
    bool overrun = false;
    const double a = wedge_angle(m_, t, e, &overrun);
    if (overrun) fault("the walk round a vertex of the quality floor did not end", m_.vertex(t, e));
    return a;
  }
  Side side_between(VertexId a, VertexId b) {
    bool overrun = false;
    const Side s = m_.side_between(a, b, &overrun);
    if (overrun) fault("the walk round a vertex of the quality floor did not end", a);
    return s;
  }
  void sync_space() {
    const std::size_t from = x_.size(), n = m_.num_vertices();
    if (from >= n) return;
    x_.resize(n);
    floor_scan(threads_, n - from, [&](std::size_t begin, std::size_t end) {
      for (std::size_t v = from + begin; v < from + end; ++v)
        x_[v] = face_.space(VertexId{static_cast<std::uint32_t>(v)});
    });
  }
  /// The live triangles with rho < q_ ((rho, slot) by slot) and the lowest rho of all
  /// (exact when below q_), measured on the threads; after the first scan only the slots
  /// that can have changed, when the store has an undo journal (see the definition).
  std::vector<std::pair<double, std::uint32_t>> scan_below(double* lowest);
  double rho3(TriId t) const {
    return rho(x_[m_.vertex(t, 0).value], x_[m_.vertex(t, 1).value], x_[m_.vertex(t, 2).value]);
  }
  double len3(Side s) const { return norm(x_[m_.org(s).value] - x_[m_.dest(s).value]); }
  /// The sharp corner of t (kNone when none), its wedge angle in *angle.
  VertexId sharp_corner(TriId t, double* angle);
  /// Every corner whose wedge is narrower than limit_ (sharp_all_, by vertex id).
  void find_sharp_corners();
  /// One change for the bad triangle t; false when none could be made.
  bool improve(TriId t);
  /// Splits the curve edge of s at its curve midpoint unless a triangle it makes would
  /// have rho <= must_beat (the bad triangle's: the worst never gets worse).
  bool split_curve_edge(Side s, double must_beat, std::span<const double> fractions = kSplitFractions);
  /// A triangle alone in a corner's wedge (its two sides at a model vertex are curve
  /// edges) with legs of unequal length: the longer one cut at the shorter one's length
  /// from the corner. See the definition.
  bool equalise_corner(TriId t, double must_beat);
  /// The split of the curve edge a - b at its curve point p (either side of the chord).
  /// Where the curve bends into the face further than the triangle there reaches (a thin
  /// triangle on a long coast edge: p beyond its far sides, so the two halves would turn
  /// over), those far sides are flipped first, at most kMaxFlips of them; everything is
  /// put back when no triangle can hold p or a triangle made would be <= must_beat.
  VertexId split_with_flips(VertexId a, VertexId b, Vec2 p, double must_beat);
  /// Whether the boundary may go from a - b (the edge of s) to a - p - b with p beyond it
  /// (outside the face there): no constrained edge near it meets a - p or p - b (but at a
  /// and b) and no vertex near it lies in the triangle a, p, b.
  bool bulge_is_clear(Side s, Vec2 p);
  void touched(VertexId v);
  /// Walks straight from the centroid of t towards p (mesh/locate.h's SegmentWalker): the
  /// constrained (or hull) side it stopped at, or none with *reached the triangle that
  /// holds p. Both none when p is not finite or the walk did not end.
  Side blocking_side(TriId t, Vec2 p, TriId* reached);

  TriangleStore& m_;
  const FloorFace& face_;
  double q_, limit_;
  bool never_below_start_;
  int threads_;
  PointInserter ins_;
  std::vector<Vec3> x_;
  std::vector<TriId> touched_;
  double worst_start_ = 1;
  std::vector<SharpCorner> sharp_all_;
  std::vector<TriId> near_;
  // scan_below's slots to measure after the first scan, and those below q at it.
  bool scanned_once_ = false;
  const StoreUndo* journal_at_scan_ = nullptr;
  std::vector<std::uint32_t> slots_, start_below_;
  QualityFloorResult res_;
  std::uint64_t work_ = 0, budget_ = ~std::uint64_t{0};
};

VertexId Floor::sharp_corner(TriId t, double* angle) {
  for (std::uint32_t e = 0; e < 3; ++e) {
    const VertexId v = m_.vertex(t, e);
    if (!face_.is_corner(v)) continue;
    const double a = wedge(t, e);
    if (a < limit_) {
      *angle = a;
      return v;
    }
  }
  // Near a sharp corner the wedge is too narrow for its triangles' edges as well (their
  // corners lie on both sides of it): those within two of their longest edges of it
  // belong to it. Splitting there would only grade towards a corner that cannot be met.
  const Vec2 p[3] = {m_.pos(m_.vertex(t, 0)), m_.pos(m_.vertex(t, 1)), m_.pos(m_.vertex(t, 2))};
  const double reach = 2 * std::sqrt(std::max({norm2(p[1] - p[0]), norm2(p[2] - p[1]), norm2(p[0] - p[2])}));
  for (const SharpCorner& c : sharp_all_) {
    const Vec2 x = m_.pos(c.v);
    if (std::min({norm(p[0] - x), norm(p[1] - x), norm(p[2] - x)}) <= reach) {
      *angle = c.degrees * kPi / 180;
      return c.v;
    }
  }
  return VertexId{};
}

void Floor::find_sharp_corners() {
  // The corners of the live triangles found on the threads (by slot, then corner), their
  // wedges measured here in that order (a walk that does not end is a fault).
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(floor_scan_chunks(m_.num_slots()));
  floor_scan(threads_, m_.num_slots(), [&](std::size_t begin, std::size_t end) {
    auto& out = found[begin / kFloorScanChunk];
    for (std::size_t t = begin; t < end; ++t) {
      if (!m_.alive(TriId{static_cast<std::uint32_t>(t)})) continue;
      for (std::uint32_t e = 0; e < 3; ++e)
        if (face_.is_corner(m_.vertex(TriId{static_cast<std::uint32_t>(t)}, e)))
          out.emplace_back(static_cast<std::uint32_t>(t), e);
    }
  });
  for (const auto& chunk : found)
    for (const auto& [t, e] : chunk) {
      const double a = wedge(TriId{t}, e);
      if (a < limit_) sharp_all_.push_back({m_.vertex(TriId{t}, e), a * 180 / kPi});
    }
  std::sort(sharp_all_.begin(), sharp_all_.end(), [](const SharpCorner& a, const SharpCorner& b) {
    return a.v.value != b.v.value ? a.v.value < b.v.value : a.degrees < b.degrees;
  });
  sharp_all_.erase(std::unique(sharp_all_.begin(), sharp_all_.end(),
                               [](const SharpCorner& a, const SharpCorner& b) { return a.v == b.v; }),
                   sharp_all_.end());
}

void Floor::touched(VertexId v) {
  // Every live triangle round v (its fan, open on a constrained edge's side).
  if (!m_.out_side_ok(v)) return;
  const FanEnd end = for_each_fan_side(m_, m_.out_side[v.value], [&](Side s) { touched_.push_back(tri_of(s)); });
  if (end == FanEnd::Corrupt) fault("the walk round a new vertex of the quality floor did not end", v);
}

bool Floor::bulge_is_clear(Side s, Vec2 p) {
  // What could lie in the bulge is near the edge: the triangles within kRings steps of it
  // (across any edge; the bulge is no larger than its chord, and the triangles there are
  // no smaller than the bad one being worked on) are searched, not the whole face.
  constexpr int kRings = 4;
  const VertexId a = m_.org(s), b = m_.dest(s);
  const Vec2 pa = m_.pos(a), pb = m_.pos(b);
  near_.clear();
  near_.push_back(tri_of(s));
  m_.will_change_tri(tri_of(s));
  m_.tri_flags[tri_of(s).value] |= kMark;
  for (std::size_t begin = 0, ring = 0; ring < kRings; ++ring) {
    const std::size_t end = near_.size();
    for (std::size_t i = begin; i < end; ++i)
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side o = m_.twin[side_of(near_[i], e).value];
        if (!o.valid() || (m_.tri_flags[tri_of(o).value] & kMark)) continue;
        m_.will_change_tri(tri_of(o));
        m_.tri_flags[tri_of(o).value] |= kMark;
        near_.push_back(tri_of(o));
      }
    begin = end;
  }
  bool clear = true;
  for (const TriId t : near_) {
    m_.tri_flags[t.value] &= static_cast<std::uint8_t>(~kMark);
    for (std::uint32_t e = 0; e < 3 && clear; ++e) {
      const VertexId v = m_.vertex(t, e);
      if (v != a && v != b) {
        const Vec2 x = m_.pos(v);
        // Closed triangle b, a, p (counter-clockwise when p is beyond a - b).
        if (orient2d(pb, pa, x) != Sign::Negative && orient2d(pa, p, x) != Sign::Negative &&
            orient2d(p, pb, x) != Sign::Negative)
          clear = false;
      }
      const Side x = side_of(t, e);
      if (!m_.constrained(x)) continue;
      const VertexId u = m_.org(x), w = m_.dest(x);
      if (u == a || u == b || w == a || w == b) continue;
      if (segments_meet(pa, p, m_.pos(u), m_.pos(w)) || segments_meet(p, pb, m_.pos(u), m_.pos(w))) clear = false;
    }
  }
  return clear;
}

Side Floor::blocking_side(TriId t, Vec2 p, TriId* reached) {
  *reached = TriId{};
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return Side{};
  const Vec2 g = (m_.pos(m_.vertex(t, 0)) + m_.pos(m_.vertex(t, 1)) + m_.pos(m_.vertex(t, 2))) / 3.0;
  SegmentWalker w{m_, g, p};
  const WalkResult r = walk_to(w, p, t.value, m_.num_slots());
  switch (r.end) {
    case WalkEnd::Found: *reached = TriId{r.tri}; return Side{};
    case WalkEnd::Blocked: return w.wall;
    case WalkEnd::StepLimit: break;
  }
  fault("the walk through the face of the quality floor did not end", m_.vertex(t, 0));
  return Side{};
}

VertexId Floor::split_with_flips(VertexId a, VertexId b, Vec2 p, double must_beat) {
  constexpr int kMaxFlips = 4;
  if (!spend()) return VertexId{};
  // What the flips change, to put back exactly (the same triangle in the same slot: the
  // caller holds triangle and side ids): an undo log of every value a flip writes (the
  // corners and flags of its two slots, the twin of their sides and of the sides across
  // the quad, the out_side of its four corners), replayed backwards. (Saving each slot
  // once, when first flipped, is not enough: a slot first flipped by the second flip may
  // have had its twins rewritten by the first, and putting those back left twins pointing
  // at the wrong sides, cavities that do not close and fans that never end.)
  struct Undo {
    enum Kind : std::uint8_t { Corner, Flags, Twin, Out } kind;
    std::uint32_t at;
    std::uint32_t value;
  };
  constexpr int kPerFlip = 6 + 6 + 10 + 4;
  Undo undo[kMaxFlips * kPerFlip];
  int n_undo = 0;
  const auto log_flip = [&](Side far) {
    const Side o = m_.twin[far.value];
    for (const TriId t : {tri_of(far), tri_of(o)})
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side x = side_of(t, e);
        undo[n_undo++] = {Undo::Corner, x.value, m_.corner[x.value].value};
        undo[n_undo++] = {Undo::Flags, x.value, m_.side_flags[x.value]};
        undo[n_undo++] = {Undo::Twin, x.value, m_.twin[x.value].value};
        const Side y = m_.twin[x.value];
        if (y.valid() && tri_of(y) != tri_of(far) && tri_of(y) != tri_of(o))
          undo[n_undo++] = {Undo::Twin, y.value, m_.twin[y.value].value};
      }
    for (const VertexId v : {m_.org(far), m_.dest(far), m_.apex(far), m_.apex(o)})
      undo[n_undo++] = {Undo::Out, v.value, m_.out_side[v.value].value};
  };
  const auto put_back = [&] {
    for (int i = n_undo - 1; i >= 0; --i) {
      const Undo& u = undo[i];
      // The slots and vertices were first changed by the flips logged, so the store's
      // own journal (store_undo.h) holds them already; told again all the same.
      if (u.kind == Undo::Out)
        m_.will_change_vertex(VertexId{u.at});
      else
        m_.will_change_tri_of(Side{u.at});
      switch (u.kind) {
        case Undo::Corner: m_.corner[u.at] = VertexId{u.value}; break;
        case Undo::Flags: m_.side_flags[u.at] = static_cast<std::uint8_t>(u.value); break;
        case Undo::Twin: m_.twin[u.at] = Side{u.value}; break;
        case Undo::Out: m_.out_side[u.at] = Side{u.value}; break;
      }
    }
  };
  TriId kept[kMaxFlips];   // the triangle of each flip that the split leaves as it is
  int flips = 0;
  const Vec3 xp = face_.to_space(p);
  for (;;) {
    // The side of a - b whose triangle must hold p: the face's side where p is on it (a
    // point beyond a hull edge widens the face: split_curve_edge checked the bulge).
    Side s = side_between(a, b);
    if (!s.valid()) s = side_between(b, a);
    if (!s.valid()) break;
    if (orient2d(m_.pos(m_.org(s)), m_.pos(m_.dest(s)), p) == Sign::Negative && m_.twin[s.value].valid())
      s = m_.twin[s.value];
    const VertexId x = m_.org(s), y = m_.dest(s), z = m_.apex(s);
    // A far side p is not strictly left of: flipped (not a constraint, the quad strictly
    // convex), so that the triangle on a - b reaches further into the face.
    Side far;
    if (orient2d(m_.pos(y), m_.pos(z), p) != Sign::Positive) far = next(s);
    else if (orient2d(m_.pos(z), m_.pos(x), p) != Sign::Positive) far = prev(s);
    if (!far.valid()) {
      bool good = true;
      for (const Side side : {s, m_.twin[s.value]}) {
        if (!side.valid()) continue;
        const Vec3 xa = x_[m_.org(side).value], xb = x_[m_.dest(side).value], xc = x_[m_.apex(side).value];
        good = good && std::min(rho(xa, xp, xc), rho(xp, xb, xc)) > must_beat;
      }
      for (int i = 0; i < flips && good; ++i) good = rho3(kept[i]) > must_beat;
      const VertexId v = good ? split_edge(m_, s, p, /*allow_constrained=*/true) : VertexId{};
      if (!v.valid()) break;
      for (int i = 0; i < flips; ++i) touched_.push_back(kept[i]);
      return v;
    }
    if (flips == kMaxFlips || m_.constrained(far) || !m_.twin[far.value].valid()) break;
    const Side o = m_.twin[far.value];
    const Vec2 f0 = m_.pos(m_.org(far)), f1 = m_.pos(m_.dest(far)), c = m_.pos(m_.apex(far)), d = m_.pos(m_.apex(o));
    if (orient2d(c, f0, d) != Sign::Positive || orient2d(d, f1, c) != Sign::Positive) break;
    log_flip(far);
    const Side made = m_.flip(far);
    // Of the two new triangles, the one without the edge a - b.
    const TriId t1 = tri_of(made), t2 = tri_of(m_.twin[made.value]);
    bool t1_has_ab = false;
    for (std::uint32_t e = 0; e < 3; ++e) {
      const VertexId u = m_.vertex(t1, e), w = m_.vertex(t1, (e + 1) % 3);
      t1_has_ab = t1_has_ab || (u == a && w == b) || (u == b && w == a);
    }
    kept[flips++] = t1_has_ab ? t2 : t1;
  }
  put_back();
  return VertexId{};
}

bool Floor::split_curve_edge(Side s, double must_beat, std::span<const double> fractions) {
  if (!face_.curve_point) return false;
  const VertexId a = m_.org(s), b = m_.dest(s);
  // The curve's parameter midpoint first; where the curve bulges so far from its chord that
  // a triangle beside it would turn over (a narrow inlet's tip between two nodes), points
  // nearer the ends, which bulge less.
  for (const double f : fractions) {
    const std::optional<Vec2> p = face_.curve_point(a, b, f);
    if (!p) return false;
    // The face lies left of a -> b (its triangle tri_of(s)); a point to the right widens it.
    if (orient2d(m_.pos(a), m_.pos(b), *p) == Sign::Negative && !bulge_is_clear(s, *p)) continue;
    const VertexId v = split_with_flips(a, b, *p, must_beat);
    if (!v.valid()) continue;
    face_.curve_split_done(a, b, v);
    ++res_.curve_splits;
    sync_space();
    touched(v);
    return true;
  }
  return false;
}

bool Floor::equalise_corner(TriId t, double must_beat) {
  // In a wedge of 13 degrees, legs 1 : 2 give rho 0.09 and halving the longer leg only
  // moves the ratio between 1 : 2 and 2 : 1, round after round, towards the corner; legs
  // of equal length give the isoceles triangle of the wedge's angle, which reaches q when
  // the wedge is wider than the sharp limit (narrower ones are not worked on). Wedges
  // wider than 120 degrees are left to the other changes: their isoceles triangle is flat.
  constexpr double kLegRatio = 1.5, kWidestWedge = 2 * kPi / 3;
  for (std::uint32_t e = 0; e < 3; ++e) {
    const VertexId v = m_.vertex(t, e);
    const Side out = side_of(t, e), in = side_of(t, (e + 2) % 3);   // v -> w, u -> v
    if (!face_.is_corner(v) || !m_.constrained(out) || !m_.constrained(in)) continue;
    const double angle = corner_angle(m_, t, e);
    if (!(angle > limit_ && angle < kWidestWedge)) continue;
    const double lo = len3(out), li = len3(in);
    const double shorter = std::min(lo, li), longer = std::max(lo, li);
    if (!(longer > kLegRatio * shorter)) continue;
    const Side leg = lo > li ? out : in;
    const VertexId w = lo > li ? m_.dest(out) : m_.org(in);
    // The curve point at `shorter` from v (in space), by bisection on the parameter.
    const Vec3 xv = x_[v.value];
    double f0 = 0, f1 = 1;
    for (int i = 0; i < 40; ++i) {
      const double f = 0.5 * (f0 + f1);
      const std::optional<Vec2> p = face_.curve_point(v, w, f);
      if (!p) return false;
      (norm(face_.to_space(*p) - xv) < shorter ? f0 : f1) = f;
    }
    const double from_v = 0.5 * (f0 + f1);
    const double from_org[] = {m_.org(leg) == v ? from_v : 1 - from_v};
    if (split_curve_edge(leg, must_beat, from_org)) return true;
  }
  return false;
}

bool Floor::improve(TriId t) {
  if (!spend()) return false;
  // The sides of t, longest first (in space), id order on ties.
  std::pair<double, std::uint32_t> by_len[3];
  for (std::uint32_t e = 0; e < 3; ++e) by_len[e] = {-len3(side_of(t, e)), e};
  std::sort(by_len, by_len + 3);
  const Side longest = side_of(t, by_len[0].second);
  // A change may make a triangle worse than t, as Ruppert's refinement does: a narrow
  // inlet's coast is split down to its width through slivers the next rounds split on.
  // With never_below_start (the second try of a face that ended worse than it started),
  // never worse than half of t nor than the worst triangle at the start.
  const double r = never_below_start_ ? std::max(0.5 * rho3(t), worst_start_) : 0.0;
  if (equalise_corner(t, r)) return true;
  if (m_.constrained(longest) && split_curve_edge(longest, r)) return true;
  // A sliver between two coasts: its circumcentre lies far beyond them; a triangle near
  // a curve: its circumcentre may crowd the curve. Either way the curve edge is split.
  const Vec2 a = m_.pos(m_.vertex(t, 0)), b = m_.pos(m_.vertex(t, 1)), c = m_.pos(m_.vertex(t, 2));
  const Vec2 cc = circumcentre(a, b, c);
  // Ruppert's rule: a circumcentre beyond a curve, as seen from t, is not inserted; the
  // curve edge in the way is split.
  TriId at;
  const Side blocked = blocking_side(t, cc, &at);
  if (blocked.valid() && split_curve_edge(blocked, r)) return true;
  // A curve edge whose diametral circle holds cc, among the sides of the triangles within
  // two steps of `u` (the point's cavity reaches them; a point that close to a curve
  // would leave a sliver on it): Ruppert's encroachment, which splits the edge instead.
  auto encroached = [&](TriId u) {
    TriId ring[1 + 3 + 6];
    std::uint32_t n = 0;
    ring[n++] = u;
    for (std::uint32_t i = 0; i < n && i < 4; ++i)
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side s = side_of(ring[i], e);
        if (m_.constrained(s) || !m_.twin[s.value].valid()) continue;
        const TriId w = tri_of(m_.twin[s.value]);
        if (std::find(ring, ring + n, w) == ring + n && n < 10) ring[n++] = w;
      }
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t e = 0; e < 3; ++e) {
        const Side s = side_of(ring[i], e);
        if (!m_.constrained(s)) continue;
        const Vec2 e0 = m_.pos(m_.org(s)), e1 = m_.pos(m_.dest(s));
        if (dot(e0 - cc, e1 - cc) < 0) return s;   // inside the edge's diametral circle
      }
    return Side{};
  };
  if (at.valid()) {
    const Side enc = encroached(at);
    if (enc.valid() && split_curve_edge(enc, r)) return true;
    if (!enc.valid() && spend() && ins_.insert(cc, at) == InsertOutcome::Inserted) {
      ++res_.interior_points;
      sync_space();
      for (std::uint32_t slot : ins_.created()) touched_.push_back(TriId{slot});
      return true;
    }
  }
  // Its other curve sides, longest first; never one much shorter than the longest: that
  // is the short side of a needle, and halving it makes two needles (a fan of them
  // round the far corner, round after round).
  for (const auto& [neg_len, e] : by_len)
    if (neg_len < 0.5 * by_len[0].first && m_.constrained(side_of(t, e)) && split_curve_edge(side_of(t, e), r))
      return true;
  // All three corners on the coast across a strait narrower than the coast's edges (or
  // the circumcentre beyond the coast): the coast edges at its corners are split, longest
  // first, so that their spacing comes down to the width. (Splitting the sliver's own
  // edges at their midpoints would only make thinner slivers.)
  Side cand[16];
  std::uint32_t nc = 0;
  for (std::uint32_t e = 0; e < 3; ++e) {
    const VertexId v = m_.vertex(t, e);
    if (!m_.out_side_ok(v)) continue;
    // Round v (the fan may be open): the constrained sides leaving or reaching v, as many
    // as cand holds (a corrupt fan ends the walk; the candidates met so far are tried).
    for_each_fan_side(m_, m_.out_side[v.value], [&](Side x) {
      if (m_.constrained(x)) cand[nc++] = x;
      if (m_.constrained(prev(x))) cand[nc++] = prev(x);
      return nc + 2 <= 16;
    });
    if (nc + 2 > 16) break;
  }
  std::sort(cand, cand + nc, [&](Side p, Side q) {
    const double lp = len3(p), lq = len3(q);
    return lp != lq ? lp > lq : p.value < q.value;
  });
  for (std::uint32_t i = 0; i < nc; ++i) {
    if (i > 0 && cand[i] == cand[i - 1]) continue;
    // Only edges longer than the triangle's longest: shorter ones are not what makes it thin.
    if (len3(cand[i]) <= -by_len[0].first) break;
    if (split_curve_edge(cand[i], r)) return true;
  }
  return false;
}

std::vector<std::pair<double, std::uint32_t>> Floor::scan_below(double* lowest) {
  struct Chunk {
    std::vector<std::pair<double, std::uint32_t>> below;
    double lowest = 1;
  };
  // With the store's undo journal started before the first scan (face_floor.cpp), a slot
  // it never saw change, below the slots it started with, keeps its rho: only the slots
  // below q at that scan, those changed since and the new ones can be below q now. The
  // same list as the whole scan, in the same slot order; the lowest rho among them is
  // the lowest of all whenever it is below q (the only case where it is used).
  const StoreUndo* journal = m_.undo_link.journal;
  const bool partial =
      journal && scanned_once_ && journal == journal_at_scan_ && journal->start_slots() <= m_.num_slots();
  if (partial) {
    slots_.assign(start_below_.begin(), start_below_.end());
    journal->changed_slots(slots_);
    for (std::uint32_t t = journal->start_slots(); t < m_.num_slots(); ++t) slots_.push_back(t);
    std::sort(slots_.begin(), slots_.end());
    slots_.erase(std::unique(slots_.begin(), slots_.end()), slots_.end());
  }
  const std::size_t n = partial ? slots_.size() : m_.num_slots();
  std::vector<Chunk> chunks(floor_scan_chunks(n));
  floor_scan(threads_, n, [&](std::size_t begin, std::size_t end) {
    Chunk& c = chunks[begin / kFloorScanChunk];
    for (std::size_t i = begin; i < end; ++i) {
      const TriId t{partial ? slots_[i] : static_cast<std::uint32_t>(i)};
      if (!m_.alive(t)) continue;
      const double r = rho3(t);
      c.lowest = std::min(c.lowest, r);   // the minimum of the doubles: any grouping gives it
      if (r < q_) c.below.emplace_back(r, t.value);
    }
  });
  std::vector<std::pair<double, std::uint32_t>> below;
  std::size_t count = 0;
  for (const Chunk& c : chunks) count += c.below.size();
  below.reserve(count);
  for (const Chunk& c : chunks) {
    *lowest = std::min(*lowest, c.lowest);
    below.insert(below.end(), c.below.begin(), c.below.end());
  }
  if (!scanned_once_) {
    scanned_once_ = true;
    journal_at_scan_ = journal;
    start_below_.clear();
    for (const auto& [r, t] : below) start_below_.push_back(t);
  }
  return below;
}

QualityFloorResult Floor::run(const QualityFloorOptions& opt) {
  sync_space();
  find_sharp_corners();
  std::vector<std::pair<double, std::uint32_t>> bad;
  auto collect = [&](bool count_sharp) {
    bad.clear();
    res_.at_sharp = 0;
    std::uint32_t below = 0;
    double lowest = 1;
    const auto under = scan_below(&lowest);
    worst_start_ = std::min(worst_start_, lowest);
    for (const auto& [r, t] : under) {
      ++below;
      double angle = 0;
      const VertexId v = sharp_corner(TriId{t}, &angle);
      if (v.valid()) {
        ++res_.at_sharp;
        if (count_sharp) res_.sharp.push_back({v, angle * 180 / kPi});
        continue;
      }
      bad.push_back({r, t});
    }
    std::sort(bad.begin(), bad.end());
    return below;
  };
  res_.below_before = collect(false);
  res_.worst_before = worst_start_;
  const std::uint32_t budget = opt.max_points ? opt.max_points : 4 * res_.below_before + 256;
  budget_ = opt.max_work
                ? opt.max_work
                : 16 * std::uint64_t{res_.below_before} + 64 * std::uint64_t(std::max(opt.max_rounds, 0)) + 1024;
  res_.work_budget = budget_;
  for (int round = 0; round < opt.max_rounds && !bad.empty() && !stopped(); ++round) {
    ++res_.rounds;
    touched_.clear();
    bool any = false;
    for (const auto& [r0, slot] : bad) {
      if (res_.curve_splits + res_.interior_points >= budget || stopped()) break;
      const TriId t{slot};
      // Earlier changes this round may have removed or mended it (or reused its slot).
      double angle = 0;
      if (!m_.alive(t) || !(rho3(t) < q_) || sharp_corner(t, &angle).valid()) continue;
      any |= improve(t);
    }
    if (!res_.fault.empty()) break;
    make_delaunay_around(m_, touched_);
    collect(false);
    if (!any || res_.curve_splits + res_.interior_points >= budget) break;
  }
  res_.work = work_;
  res_.out_of_work = work_ >= budget_ && !bad.empty();
  res_.out_of_budget = !bad.empty();
  if (!res_.fault.empty()) return res_;   // the caller puts the face back
  res_.below_after = collect(true);
  // One entry per corner (the smallest wedge angle seen there), by vertex id.
  std::sort(res_.sharp.begin(), res_.sharp.end(), [](const SharpCorner& a, const SharpCorner& b) {
    return a.v.value != b.v.value ? a.v.value < b.v.value : a.degrees < b.degrees;
  });
  res_.sharp.erase(std::unique(res_.sharp.begin(), res_.sharp.end(),
                               [](const SharpCorner& a, const SharpCorner& b) { return a.v == b.v; }),
                   res_.sharp.end());
  return res_;
}

}  // namespace

double sharp_angle_limit(double q) {
  if (!(q > 0)) return 0;
  // isoceles_rho rises from 0 at a = 0 to 1 at a = pi/3: bisection.
  double lo = 0, hi = kPi / 3;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (isoceles_rho(mid) < q ? lo : hi) = mid;
  }
  return hi;
}

QualityFloorResult raise_quality_floor(TriangleStore& m, const FloorFace& face, const QualityFloorOptions& opt) {
  if (!(opt.floor > 0)) return {};
  Floor f(m, face, opt);
  return f.run(opt);
}

std::uint32_t count_below(const TriangleStore& m, const std::function<Vec3(VertexId)>& space, double q,
                          double* worst, int threads) {
  struct Chunk {
    std::uint32_t n = 0;
    double w = 1;
  };
  std::vector<Chunk> chunks(floor_scan_chunks(m.num_slots()));
  floor_scan(std::max(1, threads), m.num_slots(), [&](std::size_t begin, std::size_t end) {
    Chunk& c = chunks[begin / kFloorScanChunk];
    for (std::size_t slot = begin; slot < end; ++slot) {
      const TriId t{static_cast<std::uint32_t>(slot)};
      if (!m.alive(t)) continue;
      const double r = rho(space(m.vertex(t, 0)), space(m.vertex(t, 1)), space(m.vertex(t, 2)));
      c.n += r < q;
      c.w = std::min(c.w, r);
    }
  });
  std::uint32_t n = 0;
  double w = 1;
  for (const Chunk& c : chunks) n += c.n, w = std::min(w, c.w);
  if (worst) *worst = w;
  return n;
}

std::pair<TriId, double> worst_triangle(const TriangleStore& m, const std::function<Vec3(VertexId)>& space,
                                        int threads) {
  // Per chunk its first strict minimum; across chunks, in chunk order, the first strict
  // minimum again: the serial scan's answer.
  std::vector<std::pair<TriId, double>> chunks(floor_scan_chunks(m.num_slots()), {TriId{}, 2.0});
  floor_scan(std::max(1, threads), m.num_slots(), [&](std::size_t begin, std::size_t end) {
    auto& [wt, worst] = chunks[begin / kFloorScanChunk];
    for (std::size_t slot = begin; slot < end; ++slot) {
      const TriId t{static_cast<std::uint32_t>(slot)};
      if (!m.alive(t)) continue;
      const double r = rho(space(m.vertex(t, 0)), space(m.vertex(t, 1)), space(m.vertex(t, 2)));
      if (r < worst) worst = r, wt = t;
    }
  });
  std::pair<TriId, double> best{TriId{}, 2.0};
  for (const auto& c : chunks)
    if (c.second < best.second) best = c;
  return best;
}

}  // namespace sm
