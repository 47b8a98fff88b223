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

#include "base/parallel.h"
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
Bez to_bezier(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3) {
  return {joint(p0, p1, p2), third(p1, p2), third(p2, p1), joint(p1, p2, p3)};
}

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
  std::uint32_t id;     // the span's index among all spans of all loops
  std::uint32_t next;   // the id of the span starting where this one ends
  double tol;
  bool active;          // tested (SplineLoop::active)
};

// The spans of one loop, numbered along it (periodic: span s follows segment s; pieces:
// each piece of m points, its end points tripled, has m + 1 spans, span j on its points
// j-2 .. j+1 clamped). Segments never decrease along the numbering.
struct LoopSpans {
  const SplineLoop& L;
  std::uint32_t n;
  std::vector<std::uint32_t> starts;       // pieces: first point of each (0 first)
  std::vector<std::uint32_t> first_span;   // pieces: first span of each, then the count

  explicit LoopSpans(const SplineLoop& loop) : L(loop), n(static_cast<std::uint32_t>(loop.pts.size())) {
    if (L.periodic) return;
    starts.assign(L.piece_start.begin(), L.piece_start.end());
    if (starts.empty() || starts[0] != 0) starts.insert(starts.begin(), 0);
    first_span.push_back(0);
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const std::uint32_t b = k + 1 < starts.size() ? starts[k + 1] : n;
      first_span.push_back(first_span.back() + (b - starts[k] + 2));   // m + 1 spans, m = b - a + 1
    }
  }
  std::uint32_t count() const { return L.periodic ? n : first_span.back(); }
  // How many spans each() hands to f for `want` (their Beziers not made).
  template <class Want>
  std::size_t count_if(Want&& want) const {
    std::size_t c = 0;
    if (L.periodic) {
      for (std::uint32_t s = 0; s < n; ++s) c += want(s) ? 1 : 0;
      return c;
    }
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const std::uint32_t a = starts[k];
      const std::uint32_t m = (k + 1 < starts.size() ? starts[k + 1] : n) - a + 1;
      for (std::uint32_t j = 0; j <= m; ++j) c += want(a + std::clamp<std::uint32_t>(j, 1, m - 1) - 1) ? 1 : 0;
    }
    return c;
  }
  // Calls f(local span, segment, Bezier, next local span) for the spans whose segment
  // `want` accepts, in order; the Bezier is made only for those.
  template <class Want, class F>
  void each(Want&& want, F&& f) const {
    if (L.periodic) {
      for (std::uint32_t s = 0; s < n; ++s)
        if (want(s))
          f(s, s, to_bezier(L.pts[(s + n - 1) % n], L.pts[s], L.pts[(s + 1) % n], L.pts[(s + 2) % n]), (s + 1) % n);
      return;
    }
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const std::uint32_t a = starts[k];
      const std::uint32_t b = k + 1 < starts.size() ? starts[k + 1] : n;
      const std::uint32_t m = b - a + 1;
      auto q = [&](std::int64_t j) {
        return L.pts[(a + static_cast<std::uint32_t>(std::clamp<std::int64_t>(j, 0, m - 1))) % n];
      };
      for (std::uint32_t j = 0; j <= m; ++j) {
        const std::uint32_t seg = a + std::clamp<std::uint32_t>(j, 1, m - 1) - 1;
        if (!want(seg)) continue;
        const std::uint32_t next = j < m ? first_span[k] + j + 1 : first_span[(k + 1) % starts.size()];
        f(first_span[k] + j, seg,
          to_bezier(q(std::int64_t{j} - 2), q(std::int64_t{j} - 1), q(j), q(std::int64_t{j} + 1)), next);
      }
    }
  }
};

// Segments are looked at in blocks of this many: a block's box (its control points) holds
// the boxes of the spans following its segments.
constexpr std::uint32_t kSpanBlock = 32;

struct Box {
  Vec2 lo, hi;
};

bool boxes_meet(const Box& a, const Box& b) {
  return !(a.lo.x > b.hi.x || b.lo.x > a.hi.x || a.lo.y > b.hi.y || b.lo.y > a.hi.y);
}

// Per loop and block of segments: whether a span following one of its segments can meet
// an active span (its block holds an active segment, or its box meets an active span's
// box). Only pairs with an active span are tested, so the other spans need not be made.
std::vector<std::vector<char>> blocks_near_active(std::span<const SplineLoop> loops) {
  std::vector<std::vector<char>> need(loops.size());
  std::vector<Box> active;   // the active spans' boxes
  std::vector<Box> blocks;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> block_at;   // (loop, block)
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    const SplineLoop& L = loops[l];
    const auto n = static_cast<std::uint32_t>(L.pts.size());
    if (n < 3) continue;
    const bool all = L.active.size() != n;
    need[l].assign((n + kSpanBlock - 1) / kSpanBlock, all ? 1 : 0);
    if (all) continue;   // every span made: nothing to look up
    if (std::any_of(L.active.begin(), L.active.end(), [](char c) { return c != 0; })) {
      LoopSpans(L).each([&](std::uint32_t s) { return L.active[s] != 0; },
                        [&](std::uint32_t, std::uint32_t s, const Bez& b, std::uint32_t) {
                          need[l][s / kSpanBlock] = 1;
                          Box x;
                          box_of(b, x.lo, x.hi);
                          active.push_back(x);
                        });
    }
    for (std::uint32_t k = 0; k < need[l].size(); ++k) {
      if (need[l][k]) continue;
      const std::uint32_t s0 = k * kSpanBlock, s1 = std::min(n, s0 + kSpanBlock);
      Box x{L.pts[s0], L.pts[s0]};
      for (std::uint32_t i = s0 + n - 1; i <= s1 + n + 1; ++i) {   // points s0-1 .. s1+1
        const Vec2 p = L.pts[i % n];
        x.lo = {std::min(x.lo.x, p.x), std::min(x.lo.y, p.y)};
        x.hi = {std::max(x.hi.x, p.x), std::max(x.hi.y, p.y)};
      }
      blocks.push_back(x);
      block_at.push_back({l, k});
    }
  }
  if (active.empty() || blocks.empty()) return need;
  // The active boxes in a uniform grid, each block looked up in the cells its box covers.
  Box all = active[0];
  for (const Box& x : active)
    all = {{std::min(all.lo.x, x.lo.x), std::min(all.lo.y, x.lo.y)},
           {std::max(all.hi.x, x.hi.x), std::max(all.hi.y, x.hi.y)}};
  constexpr std::int64_t kCells = 256;   // a side: at most 65536 cells
  const double cx = std::max((all.hi.x - all.lo.x) / kCells, 1e-300),
               cy = std::max((all.hi.y - all.lo.y) / kCells, 1e-300);
  auto ix = [&](double x) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - all.lo.x) / cx), 0, kCells - 1);
  };
  auto iy = [&](double y) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - all.lo.y) / cy), 0, kCells - 1);
  };
  std::vector<std::uint32_t> cell_first(kCells * kCells + 1, 0), items;
  for (int pass = 0; pass < 2; ++pass) {   // count, then place (a counting sort on cells)
    if (pass == 1) {
      for (std::size_t c = 1; c < cell_first.size(); ++c) cell_first[c] += cell_first[c - 1];
      items.resize(cell_first.back());
    }
    for (std::uint32_t i = 0; i < active.size(); ++i)
      for (std::int64_t y = iy(active[i].lo.y); y <= iy(active[i].hi.y); ++y)
        for (std::int64_t x = ix(active[i].lo.x); x <= ix(active[i].hi.x); ++x) {
          if (pass == 0) ++cell_first[static_cast<std::size_t>(y * kCells + x) + 1];
          else items[cell_first[static_cast<std::size_t>(y * kCells + x)]++] = i;
        }
  }
  for (std::size_t c = cell_first.size() - 1; c > 0; --c) cell_first[c] = cell_first[c - 1];   // back to starts
  cell_first[0] = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const Box& x = blocks[k];
    if (!boxes_meet(x, all)) continue;
    bool hit = false;
    for (std::int64_t y = iy(x.lo.y); y <= iy(x.hi.y) && !hit; ++y)
      for (std::int64_t c = y * kCells + ix(x.lo.x); c <= y * kCells + ix(x.hi.x) && !hit; ++c)
        for (std::uint32_t j = cell_first[static_cast<std::size_t>(c)]; j < cell_first[static_cast<std::size_t>(c) + 1];
             ++j)
          if (boxes_meet(x, active[items[j]])) {
            hit = true;
            break;
          }
    if (hit) need[block_at[k].first][block_at[k].second] = 1;
  }
  return need;
}

// Does the pair of spans meet? (a and b distinct; each Span::next tells a joint.)
bool spans_meet(const Span& a, const Span& b, Vec2& where) {
  MeetContext cx{std::min(a.tol, b.tol), kMeetBudget, {}};
  bool meet;
  if (a.next == b.id && b.next == a.id) {   // a loop of two spans: both ends joined
    Bez a1, a2;
    split(a.b, a1, a2);
    meet = curves_meet(a2, b.b, true, cx) || curves_meet(b.b, a1, true, cx);
  } else if (a.next == b.id) {
    meet = curves_meet(a.b, b.b, true, cx);
  } else if (b.next == a.id) {
    meet = curves_meet(b.b, a.b, true, cx);
  } else {
    meet = curves_meet(a.b, b.b, false, cx);
  }
  where = cx.where;
  return meet;
}

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


std::vector<HullOverlap> find_spline_crossings(std::span<const SplineLoop> loops, int threads) {
  const std::vector<std::vector<char>> need = blocks_near_active(loops);
  // The spans are made on the threads in fixed chunks of loops, each loop's written at its
  // place in one array: a loop's span ids start after the loops before (their counts) and
  // its spans after theirs (counted first, on the threads too), so the array is one
  // thread's for every count. A continent has thousands of spans: a few loops a chunk.
  const std::size_t n_loops = loops.size();
  constexpr std::size_t kLoopChunk = 4;
  const int workers = resolve_thread_count(threads);
  std::vector<std::uint32_t> first_id(n_loops + 1, 0);
  std::vector<std::size_t> first_span(n_loops + 1, 0);
  parallel_for_chunks(workers, n_loops, kLoopChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t l = b; l < e; ++l) {
      if (loops[l].pts.size() < 3) continue;
      const LoopSpans ls(loops[l]);
      first_id[l + 1] = ls.count();
      first_span[l + 1] = ls.count_if([&](std::uint32_t s) { return need[l][s / kSpanBlock] != 0; });
    }
  });
  for (std::size_t l = 0; l < n_loops; ++l) {
    first_id[l + 1] += first_id[l];
    first_span[l + 1] += first_span[l];
  }
  std::vector<Span> spans(first_span[n_loops]);
  parallel_for_chunks(workers, n_loops, kLoopChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t li = b; li < e; ++li) {
      const SplineLoop& L = loops[li];
      const auto n = static_cast<std::uint32_t>(L.pts.size());
      if (n < 3) continue;
      const auto l = static_cast<std::uint32_t>(li);
      double fallback = 0;
      if (L.tol.size() != n) {
        Vec2 lo = L.pts[0], hi = L.pts[0];
        for (Vec2 p : L.pts)
          lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        fallback = 1e-7 * std::max(hi.x - lo.x, hi.y - lo.y);
      }
      const std::uint32_t id = first_id[l];
      std::size_t at = first_span[l];
      LoopSpans(L).each([&](std::uint32_t s) { return need[l][s / kSpanBlock] != 0; },
                        [&](std::uint32_t j, std::uint32_t s, const Bez& bz, std::uint32_t next) {
                          Span& sp = spans[at++];
                          sp = Span{bz, {}, {}, l, s, id + j, id + next, L.tol.size() == n ? L.tol[s] : fallback,
                                    L.active.size() != n || L.active[s] != 0};
                          box_of(bz, sp.lo, sp.hi);
                        });
    }
  });
  // The pairs to decide (one of them active at least), then decided on the threads in
  // fixed chunks whose finds are joined in chunk order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < spans.size(); ++i)
    if (spans[i].active) pairs.push_back({i, i});   // the span against itself
  for_box_pairs(spans, [&](std::uint32_t ia, std::uint32_t ib) {
    if (spans[ia].active || spans[ib].active) pairs.push_back({ia, ib});
  });
  constexpr std::size_t kChunk = 512;
  std::vector<std::vector<HullOverlap>> parts((pairs.size() + kChunk - 1) / kChunk);
  parallel_for_chunks(workers, pairs.size(), kChunk, [&](std::size_t begin, std::size_t end) {
    std::vector<HullOverlap>& part = parts[begin / kChunk];
    for (std::size_t k = begin; k < end; ++k) {
      const Span& a = spans[pairs[k].first];
      const Span& b = spans[pairs[k].second];
      Vec2 where;
      bool meet;
      if (&a == &b) {
        MeetContext cx{a.tol, kMeetBudget, {}};
        meet = curve_meets_itself(a.b, cx);
        where = cx.where;
      } else {
        meet = spans_meet(a, b, where);
      }
      if (!meet) continue;
      HullOverlap o{a.loop, a.seg, b.loop, b.seg, where};
      order_places(o);
      part.push_back(o);
    }
  });
  std::vector<HullOverlap> out;
  for (const std::vector<HullOverlap>& p : parts) out.insert(out.end(), p.begin(), p.end());
  // Two finds of one pair of segments (the tripled end of a piece has two spans on its
  // first segment) keep the place first in (x, y): which grid cell found them first, and
  // which spans were made, do not matter.
  std::sort(out.begin(), out.end(), [](const HullOverlap& a, const HullOverlap& b) {
    return std::tuple(place_pair_key(a), a.where.x, a.where.y) < std::tuple(place_pair_key(b), b.where.x, b.where.y);
  });
  out.erase(
      std::unique(out.begin(), out.end(),
                  [](const HullOverlap& a, const HullOverlap& b) { return place_pair_key(a) == place_pair_key(b); }),
      out.end());
  return out;
}

}  // namespace sm::coast
