// Span hulls of cubic B-splines and their overlaps (grid + exact separating-edge test).
#include "coast/spline_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

#include "mesh/predicates.h"

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
  if (a.n == 2 && b.n == 2) {   // two segments: also check the collinear case by extents
    const Sign o1 = orient2d(a.p[0], a.p[1], b.p[0]), o2 = orient2d(a.p[0], a.p[1], b.p[1]);
    if (o1 == Sign::Zero && o2 == Sign::Zero) return true;   // boxes overlap and collinear
    const Sign o3 = orient2d(b.p[0], b.p[1], a.p[0]), o4 = orient2d(b.p[0], b.p[1], a.p[1]);
    return !(o1 == o2 && o1 != Sign::Zero) && !(o3 == o4 && o3 != Sign::Zero);
  }
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
  if (hulls.size() < 2) return out;
  // Uniform grid on the boxes, cell about twice the median box extent.
  Vec2 lo = hulls[0].lo, hi = hulls[0].hi;
  std::vector<double> ext;
  for (const Hull& h : hulls) {
    lo = {std::min(lo.x, h.lo.x), std::min(lo.y, h.lo.y)};
    hi = {std::max(hi.x, h.hi.x), std::max(hi.y, h.hi.y)};
    ext.push_back(std::max(h.hi.x - h.lo.x, h.hi.y - h.lo.y));
  }
  std::nth_element(ext.begin(), ext.begin() + static_cast<long>(ext.size() / 2), ext.end());
  const double span = std::max(hi.x - lo.x, hi.y - lo.y);
  double cell = std::max({2.0 * ext[ext.size() / 2], span * 1e-7,
                          span / std::sqrt(16.0 * static_cast<double>(hulls.size()) + 1.0)});
  if (!(cell > 0)) cell = 1;
  const auto nx = static_cast<std::int64_t>((hi.x - lo.x) / cell) + 1;
  const auto ny = static_cast<std::int64_t>((hi.y - lo.y) / cell) + 1;
  auto ix = [&](double x) { return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - lo.x) / cell), 0, nx - 1); };
  auto iy = [&](double y) { return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - lo.y) / cell), 0, ny - 1); };
  std::vector<std::pair<std::int64_t, std::uint32_t>> cells;
  for (std::uint32_t k = 0; k < hulls.size(); ++k)
    for (std::int64_t y = iy(hulls[k].lo.y); y <= iy(hulls[k].hi.y); ++y)
      for (std::int64_t x = ix(hulls[k].lo.x); x <= ix(hulls[k].hi.x); ++x) cells.push_back({y * nx + x, k});
  std::sort(cells.begin(), cells.end());
  for (std::size_t i = 0; i < cells.size();) {
    std::size_t j = i;
    while (j < cells.size() && cells[j].first == cells[i].first) ++j;
    for (std::size_t p = i; p < j; ++p)
      for (std::size_t q = p + 1; q < j; ++q) {
        const Hull& a = hulls[cells[p].second];
        const Hull& b = hulls[cells[q].second];
        if (a.lo.x > b.hi.x || b.lo.x > a.hi.x || a.lo.y > b.hi.y || b.lo.y > a.hi.y) continue;
        const Vec2 corner{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y)};
        if (iy(corner.y) * nx + ix(corner.x) != cells[i].first) continue;
        if (share_points(a, b) || !hulls_overlap(a, b)) continue;
        HullOverlap o{a.loop, a.seg, b.loop, b.seg, 0.5 * (a.p[0] + b.p[0])};
        if (std::pair(o.loop_b, o.seg_b) < std::pair(o.loop_a, o.seg_a)) {
          std::swap(o.loop_a, o.loop_b);
          std::swap(o.seg_a, o.seg_b);
        }
        out.push_back(o);
      }
    i = j;
  }
  std::sort(out.begin(), out.end(), [](const HullOverlap& a, const HullOverlap& b) {
    return std::tie(a.loop_a, a.seg_a, a.loop_b, a.seg_b) < std::tie(b.loop_a, b.seg_a, b.loop_b, b.seg_b);
  });
  return out;
}

}  // namespace sm::coast
