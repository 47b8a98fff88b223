// Span hulls of cubic B-splines and their overlaps (grid + exact separating-edge test), and
// the precise crossing test: Bezier spans halved by de Casteljau while their hulls overlap.
#include "coast/spline_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>

#include "coast/place_pairs.h"
#include "exact/predicates.h"
#include "exact/segments.h"

namespace sm::coast {
namespace {

struct Hull {
  std::array<Vec2, 4> p;   // convex hull, counter-clockwise
  int n = 0;
  Vec2 lo, hi;
  std::uint32_t loop, seg;
  std::uint32_t first, count;   // control points used: first .. first+count-1 (mod loop size)
  std::uint32_t loop_size;
  bool periodic;
};

// Convex hull of up to 4 points with exact orientation tests (gift wrapping).
int convex_hull(const std::array<Vec2, 4>& in, int m, std::array<Vec2, 4>& out) {
  std::array<Vec2, 4> q{};
  int k = 0;
  for (int i = 0; i < m; ++i) {
    bool dup = false;
    for (int j = 0; j < k; ++j) dup |= q[j] == in[i];
    if (!dup) q[k++] = in[i];
  }
  if (k <= 2) {
    for (int i = 0; i < k; ++i) out[i] = q[i];
    return k;
  }
  int start = 0;
  for (int i = 1; i < k; ++i)
    if (q[i].x < q[start].x || (q[i].x == q[start].x && q[i].y < q[start].y)) start = i;
  int n = 0, cur = start;
  do {
    out[n++] = q[cur];
    int nxt = (cur + 1) % k;
    for (int i = 0; i < k; ++i) {
      if (i == cur) continue;
      const Sign s = orient2d(q[cur], q[nxt], q[i]);
      if (s == Sign::Negative || (s == Sign::Zero && norm2(q[i] - q[cur]) > norm2(q[nxt] - q[cur]))) nxt = i;
    }
    cur = nxt;
  } while (cur != start && n < 4);
  return n;
}

// True when an edge of a (or a's only segment/point) separates b strictly.
bool separated_by(const Hull& a, const Hull& b) {
  if (a.n >= 3) {
    for (int i = 0; i < a.n; ++i) {
      const Vec2 e0 = a.p[i], e1 = a.p[(i + 1) % a.n];
      bool all_out = true;
      for (int j = 0; j < b.n && all_out; ++j) all_out = orient2d(e0, e1, b.p[j]) == Sign::Negative;
      if (all_out) return true;
    }
    return false;
  }
  if (a.n == 2) {   // a segment: b entirely on one side of its line
    bool all_left = true, all_right = true;
    for (int j = 0; j < b.n; ++j) {
      const Sign s = orient2d(a.p[0], a.p[1], b.p[j]);
      all_left &= s == Sign::Positive;
      all_right &= s == Sign::Negative;
    }
    return all_left || all_right;
  }
  return false;
}

bool hulls_overlap(const Hull& a, const Hull& b) {
  if (a.lo.x > b.hi.x || b.lo.x > a.hi.x || a.lo.y > b.hi.y || b.lo.y > a.hi.y) return false;
  if (separated_by(a, b) || separated_by(b, a)) return false;
  if (a.n == 2 && b.n == 2) return segments_meet(a.p[0], a.p[1], b.p[0], b.p[1]);   // two segments
  return true;
}

bool share_points(const Hull& a, const Hull& b) {
  if (a.loop != b.loop) return false;
  const std::uint32_t n = a.loop_size;
  for (std::uint32_t i = 0; i < a.count; ++i)
    for (std::uint32_t j = 0; j < b.count; ++j)
      if ((a.first + i) % n == (b.first + j) % n) return true;
  return false;
}

// Calls f(i, j) once for each pair of items whose boxes (members lo, hi) overlap, in a
// deterministic order: a uniform grid (cell about twice the median box extent), the
// (cell, item) list sorted, a pair visited in the cell of the lower corner of the overlap.
template <class Item, class F>
void for_box_pairs(const std::vector<Item>& items, F&& f) {
  if (items.size() < 2) return;
  Vec2 lo = items[0].lo, hi = items[0].hi;
  std::vector<double> ext;
  ext.reserve(items.size());
  for (const Item& h : items) {
    lo = {std::min(lo.x, h.lo.x), std::min(lo.y, h.lo.y)};
    hi = {std::max(hi.x, h.hi.x), std::max(hi.y, h.hi.y)};
    ext.push_back(std::max(h.hi.x - h.lo.x, h.hi.y - h.lo.y));
  }
  std::nth_element(ext.begin(), ext.begin() + static_cast<long>(ext.size() / 2), ext.end());
  const double span = std::max(hi.x - lo.x, hi.y - lo.y);
  double cell = std::max({2.0 * ext[ext.size() / 2], span * 1e-7,
                          span / std::sqrt(16.0 * static_cast<double>(items.size()) + 1.0)});
  if (!(cell > 0)) cell = 1;
  const auto nx = static_cast<std::int64_t>((hi.x - lo.x) / cell) + 1;
  const auto ny = static_cast<std::int64_t>((hi.y - lo.y) / cell) + 1;
  auto ix = [&](double x) { return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - lo.x) / cell), 0, nx - 1); };
  auto iy = [&](double y) { return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - lo.y) / cell), 0, ny - 1); };
  std::vector<std::pair<std::int64_t, std::uint32_t>> cells;
  for (std::uint32_t k = 0; k < items.size(); ++k)
    for (std::int64_t y = iy(items[k].lo.y); y <= iy(items[k].hi.y); ++y)
      for (std::int64_t x = ix(items[k].lo.x); x <= ix(items[k].hi.x); ++x) cells.push_back({y * nx + x, k});
  std::sort(cells.begin(), cells.end());
  for (std::size_t i = 0; i < cells.size();) {
    std::size_t j = i;
    while (j < cells.size() && cells[j].first == cells[i].first) ++j;
    for (std::size_t p = i; p < j; ++p)
      for (std::size_t q = p + 1; q < j; ++q) {
        const Item& a = items[cells[p].second];
        const Item& b = items[cells[q].second];
        if (a.lo.x > b.hi.x || b.lo.x > a.hi.x || a.lo.y > b.hi.y || b.lo.y > a.hi.y) continue;
        const Vec2 corner{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y)};
        if (iy(corner.y) * nx + ix(corner.x) != cells[i].first) continue;
        f(cells[p].second, cells[q].second);
      }
    i = j;
  }
}

// The precise test works on the spans as cubic Beziers.
using Bez = std::array<Vec2, 4>;

// Each helper returns its input point when the points it combines are equal, so the tripled
// end points of pieces and the joint shared by consecutive spans come out bitwise identical.
Vec2 mid(Vec2 a, Vec2 b) { return a == b ? a : 0.5 * (a + b); }
Vec2 third(Vec2 a, Vec2 b) { return a == b ? a : (2.0 * a + b) / 3.0; }   // a third of the way to b
Vec2 joint(Vec2 a, Vec2 b, Vec2 c) { return a == b && b == c ? b : (a + 4.0 * b + c) / 6.0; }

// The span of the uniform cubic B-spline on control points p0..p3 as a cubic Bezier.
Bez to_bezier(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3) { return {joint(p0, p1, p2), third(p1, p2), third(p2, p1), joint(p1, p2, p3)}; }

void split(const Bez& b, Bez& l, Bez& r) {
  const Vec2 ab = mid(b[0], b[1]), bc = mid(b[1], b[2]), cd = mid(b[2], b[3]);
  const Vec2 abc = mid(ab, bc), bcd = mid(bc, cd), m = mid(abc, bcd);
  l = {b[0], ab, abc, m};
  r = {m, bcd, cd, b[3]};
}

void box_of(const Bez& b, Vec2& lo, Vec2& hi) {
  lo = hi = b[0];
  for (int i = 1; i < 4; ++i) {
    lo = {std::min(lo.x, b[i].x), std::min(lo.y, b[i].y)};
    hi = {std::max(hi.x, b[i].x), std::max(hi.y, b[i].y)};
  }
}

double extent(const Bez& b) {
  Vec2 lo, hi;
  box_of(b, lo, hi);
  return std::max(hi.x - lo.x, hi.y - lo.y);
}

Hull hull_of(const Bez& b) {
  Hull h{};
  h.n = convex_hull(b, 4, h.p);
  box_of(b, h.lo, h.hi);
  return h;
}

// Directions within an angle: [mid - half, mid + half] (radians). Angles are compared with
// a margin far above rounding, so "disjoint" is safe.
constexpr double kAngleMargin = 1e-9;
struct Arc {
  double mid = 0, half = 0;
  bool empty = true;   // only zero vectors
};

// The smallest arc holding the directions of the non-zero vectors; none when they span
// half a turn or more (their cone is not convex then).
std::optional<Arc> arc_of(std::initializer_list<Vec2> vs) {
  double ref = 0, lo = 0, hi = 0;
  bool have = false;
  for (Vec2 d : vs) {
    if (d.x == 0 && d.y == 0) continue;
    const double a = std::atan2(d.y, d.x);
    if (!have) {
      ref = a;
      have = true;
      continue;
    }
    const double o = std::remainder(a - ref, 2 * std::numbers::pi);
    lo = std::min(lo, o);
    hi = std::max(hi, o);
  }
  if (!have) return Arc{};
  if (hi - lo >= std::numbers::pi - kAngleMargin) return std::nullopt;
  return Arc{ref + 0.5 * (lo + hi), 0.5 * (hi - lo), false};
}

bool arcs_disjoint(const Arc& a, const Arc& b, double gap) {
  if (a.empty || b.empty) return true;
  return std::abs(std::remainder(a.mid - b.mid, 2 * std::numbers::pi)) > a.half + b.half + gap;
}

// Two curves leaving their joint less than this angle (radians) apart fold back onto each
// other there: a near-touch, found as meeting once the pieces are below the tolerance.
constexpr double kMinJointAngle = 1e-3;

// True when the points of b lie farther than gap outside one edge line of a (a segment a:
// on either side of it; a point a: only from a point b). Floating distances:
// the gap, a fraction of gamma, is far above rounding.
bool apart_by(const Hull& a, const Hull& b, double gap) {
  if (a.n == 1) return b.n == 1 && norm(b.p[0] - a.p[0]) > gap;   // else judged by b's edges
  for (int i = 0; i < a.n; ++i) {
    const Vec2 e0 = a.p[i], e1 = a.p[(i + 1) % a.n];
    const Vec2 e = e1 - e0;
    const double len = norm(e);
    if (!(len > 0)) continue;
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (int j = 0; j < b.n; ++j) {
      const double d = cross(e, b.p[j] - e0) / len;   // > 0: left of the edge
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    if (hi < -gap) return true;                  // right of the edge: outside a counter-clockwise hull
    if (a.n == 2 && lo > gap) return true;       // a segment: either side
  }
  return false;
}

struct MeetContext {
  double tol;
  int budget;   // sub-pair tests left; at zero the pair counts as meeting (conservative)
  Vec2 where;
};

// Do curves a and b meet (or come within tol)? Pieces are apart when their hulls are
// (exact orient2d) by more than tol; pieces below tol whose hulls are not count as meeting.
// `adjacent`: a ends where b starts (their joint, a[3] == b[0]), which does not count.
// Hull(a) lies in the cone from the joint through a's other control points, so disjoint
// cones leave the joint as the only common point.
bool curves_meet(const Bez& a, const Bez& b, bool adjacent, MeetContext& cx) {
  if (--cx.budget < 0) {
    cx.where = a[3];
    return true;
  }
  if (adjacent) {
    const Vec2 j = a[3];
    const auto ra = arc_of({a[0] - j, a[1] - j, a[2] - j}), rb = arc_of({b[1] - j, b[2] - j, b[3] - j});
    if (ra && rb && arcs_disjoint(*ra, *rb, kMinJointAngle)) return false;
  } else {
    const Hull ha = hull_of(a), hb = hull_of(b);
    const double box_gap = std::max({ha.lo.x - hb.hi.x, hb.lo.x - ha.hi.x, ha.lo.y - hb.hi.y, hb.lo.y - ha.hi.y});
    if (box_gap > cx.tol) return false;
    if (!hulls_overlap(ha, hb) && (apart_by(ha, hb, cx.tol) || apart_by(hb, ha, cx.tol))) return false;
  }
  const double ea = extent(a), eb = extent(b);
  if (ea <= cx.tol && eb <= cx.tol) {
    cx.where = adjacent ? a[3] : 0.5 * (a[0] + b[0]);
    return true;
  }
  Bez a1, a2, b1, b2;
  if (adjacent) {
    split(a, a1, a2);
    split(b, b1, b2);
    return curves_meet(a2, b1, true, cx) || curves_meet(a1, b1, false, cx) || curves_meet(a2, b2, false, cx) ||
           curves_meet(a1, b2, false, cx);
  }
  if (ea >= eb) {
    split(a, a1, a2);
    return curves_meet(a1, b, false, cx) || curves_meet(a2, b, false, cx);
  }
  split(b, b1, b2);
  return curves_meet(a, b1, false, cx) || curves_meet(a, b2, false, cx);
}

// Does the curve cross itself? Not when its derivative (a Bezier on the differences of
// the control points) keeps within less than half a turn: it then advances along one
// direction. Else halves, each half and the two halves against each other.
bool curve_meets_itself(const Bez& a, MeetContext& cx) {
  if (--cx.budget < 0) {
    cx.where = a[0];
    return true;
  }
  if (arc_of({a[1] - a[0], a[2] - a[1], a[3] - a[2]})) return false;
  if (extent(a) <= cx.tol) {
    cx.where = a[0];
    return true;
  }
  Bez a1, a2;
  split(a, a1, a2);
  return curve_meets_itself(a1, cx) || curve_meets_itself(a2, cx) || curves_meet(a1, a2, true, cx);
}

// Sub-pair tests per candidate pair before it is taken as meeting (a near-parallel pair at
// the tolerance needs about 2 log2(extent / tol) per level of a few overlapping pieces).
constexpr int kMeetBudget = 20000;

struct Span {
  Bez b;
  Vec2 lo, hi;
  std::uint32_t loop, seg;
  std::uint32_t next;   // the span starting where this one ends (index in the span list)
  double tol;
  bool active;          // tested (SplineLoop::active)
};

}  // namespace

std::vector<HullOverlap> find_hull_overlaps(std::span<const SplineLoop> loops) {
  std::vector<Hull> hulls;
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    const SplineLoop& L = loops[l];
    const auto n = static_cast<std::uint32_t>(L.pts.size());
    if (n < 2) continue;
    // Piece index of each point (pieces: a span never reaches into the next piece).
    std::vector<std::uint32_t> piece_first(n, 0), piece_end(n, n);
    if (!L.periodic) {
      for (std::size_t k = 0; k < L.piece_start.size(); ++k) {
        const std::uint32_t a = L.piece_start[k];
        const std::uint32_t b = k + 1 < L.piece_start.size() ? L.piece_start[k + 1] : n;
        for (std::uint32_t i = a; i < b; ++i) piece_first[i] = a, piece_end[i] = b;   // piece ends at point b (mod n)
      }
    }
    for (std::uint32_t s = 0; s < n; ++s) {
      Hull h;
      h.loop = l;
      h.seg = s;
      h.loop_size = n;
      h.periodic = L.periodic;
      std::array<Vec2, 4> q{};
      int m = 0;
      if (L.periodic) {
        h.first = (s + n - 1) % n;
        h.count = std::min<std::uint32_t>(4, n);
      } else {
        // Control points s-1 .. s+2 clamped to the piece [piece_first, piece_end] (the end
        // point is the next piece's first point).
        const std::uint32_t a = s > piece_first[s] ? s - 1 : s;
        const std::uint32_t b = std::min(s + 2, piece_end[s]);
        h.first = a;
        h.count = b - a + 1;
      }
      for (std::uint32_t i = 0; i < h.count; ++i) q[m++] = L.pts[(h.first + i) % n];
      h.n = convex_hull(q, m, h.p);
      h.lo = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
      h.hi = -h.lo;
      for (int i = 0; i < m; ++i) {
        h.lo = {std::min(h.lo.x, q[i].x), std::min(h.lo.y, q[i].y)};
        h.hi = {std::max(h.hi.x, q[i].x), std::max(h.hi.y, q[i].y)};
      }
      hulls.push_back(h);
    }
  }
  std::vector<HullOverlap> out;
  for_box_pairs(hulls, [&](std::uint32_t ia, std::uint32_t ib) {
    const Hull& a = hulls[ia];
    const Hull& b = hulls[ib];
    if (share_points(a, b) || !hulls_overlap(a, b)) return;
    HullOverlap o{a.loop, a.seg, b.loop, b.seg, 0.5 * (a.p[0] + b.p[0])};
    order_places(o);
    out.push_back(o);
  });
  sort_place_pairs(out);
  return out;
}

std::vector<HullOverlap> find_spline_crossings(std::span<const SplineLoop> loops) {
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::vector<Span> spans;
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    const SplineLoop& L = loops[l];
    const auto n = static_cast<std::uint32_t>(L.pts.size());
    if (n < 3) continue;
    double fallback = 0;
    if (L.tol.size() != n) {
      Vec2 lo = L.pts[0], hi = L.pts[0];
      for (Vec2 p : L.pts) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
      fallback = 1e-7 * std::max(hi.x - lo.x, hi.y - lo.y);
    }
    auto tol_at = [&](std::uint32_t i) { return L.tol.size() == n ? L.tol[i] : fallback; };
    auto active_at = [&](std::uint32_t i) { return L.active.size() != n || L.active[i] != 0; };
    const auto first = static_cast<std::uint32_t>(spans.size());
    auto add = [&](const Bez& b, std::uint32_t seg) {
      Span sp{b, {}, {}, l, seg, kNone, tol_at(seg), active_at(seg)};
      box_of(b, sp.lo, sp.hi);
      spans.push_back(sp);
    };
    if (L.periodic) {
      // Span s on points s-1 .. s+2 (wrapping) follows segment s.
      for (std::uint32_t s = 0; s < n; ++s)
        add(to_bezier(L.pts[(s + n - 1) % n], L.pts[s], L.pts[(s + 1) % n], L.pts[(s + 2) % n]), s);
      for (std::uint32_t s = 0; s < n; ++s) spans[first + s].next = first + (s + 1) % n;
    } else {
      // Each piece: points a .. b (b the next piece's first point, wrapping), end points
      // tripled: m + 1 spans for m points, span j on points j-2 .. j+1 (clamped).
      std::vector<std::uint32_t> starts(L.piece_start.begin(), L.piece_start.end());
      if (starts.empty() || starts[0] != 0) starts.insert(starts.begin(), 0);
      std::vector<std::uint32_t> piece_first_span;
      for (std::size_t k = 0; k < starts.size(); ++k) {
        const std::uint32_t a = starts[k];
        const std::uint32_t b = k + 1 < starts.size() ? starts[k + 1] : n;
        const std::uint32_t m = b - a + 1;
        auto q = [&](std::int64_t j) { return L.pts[(a + static_cast<std::uint32_t>(std::clamp<std::int64_t>(j, 0, m - 1))) % n]; };
        piece_first_span.push_back(static_cast<std::uint32_t>(spans.size()));
        for (std::uint32_t j = 0; j <= m; ++j) {
          add(to_bezier(q(std::int64_t{j} - 2), q(std::int64_t{j} - 1), q(j), q(std::int64_t{j} + 1)),
              a + std::clamp<std::uint32_t>(j, 1, m - 1) - 1);
          if (j > 0) spans[spans.size() - 2].next = static_cast<std::uint32_t>(spans.size() - 1);
        }
      }
      for (std::size_t k = 0; k < piece_first_span.size(); ++k) {
        const std::uint32_t last = k + 1 < piece_first_span.size() ? piece_first_span[k + 1] - 1
                                                                    : static_cast<std::uint32_t>(spans.size() - 1);
        spans[last].next = piece_first_span[(k + 1) % piece_first_span.size()];
      }
    }
  }
  std::vector<HullOverlap> out;
  auto found = [&](const Span& a, const Span& b, Vec2 where) {
    HullOverlap o{a.loop, a.seg, b.loop, b.seg, where};
    order_places(o);
    out.push_back(o);
  };
  for (const Span& s : spans) {
    if (!s.active) continue;
    MeetContext cx{s.tol, kMeetBudget, {}};
    if (curve_meets_itself(s.b, cx)) found(s, s, cx.where);
  }
  // Every span stays in the grid, so the pairs tested are visited in the order of a full
  // search: the same records in the same order before the sort.
  for_box_pairs(spans, [&](std::uint32_t ia, std::uint32_t ib) {
    const Span& a = spans[ia];
    const Span& b = spans[ib];
    if (!a.active && !b.active) return;
    MeetContext cx{std::min(a.tol, b.tol), kMeetBudget, {}};
    bool meet;
    if (a.next == ib && b.next == ia) {   // a loop of two spans: both ends joined
      Bez a1, a2;
      split(a.b, a1, a2);
      meet = curves_meet(a2, b.b, true, cx) || curves_meet(b.b, a1, true, cx);
    } else if (a.next == ib) {
      meet = curves_meet(a.b, b.b, true, cx);
    } else if (b.next == ia) {
      meet = curves_meet(b.b, a.b, true, cx);
    } else {
      meet = curves_meet(a.b, b.b, false, cx);
    }
    if (meet) found(a, b, cx.where);
  });
  sort_place_pairs(out);
  out.erase(std::unique(out.begin(), out.end(),
                        [](const HullOverlap& a, const HullOverlap& b) { return place_pair_key(a) == place_pair_key(b); }),
            out.end());
  return out;
}

}  // namespace sm::coast
