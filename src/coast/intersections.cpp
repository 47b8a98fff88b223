// Uniform-grid search for segment intersections. Each segment is entered in the cells its
// bounding box covers; (cell, segment) pairs are sorted so the pairs met in a cell come
// out in a fixed order, and a pair is tested only in the cell holding the lower corner of
// the overlap of its two boxes, so it is tested (and reported) once.
#include "coast/intersections.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <tuple>

#include "base/check.h"
#include "base/parallel.h"
#include "coast/place_pairs.h"
#include "exact/predicates.h"
#include "exact/segments.h"

namespace sm::coast {
namespace {

struct Seg {
  Vec2 a, b;
  std::uint32_t loop, index, n;   // n: vertex count of its loop
  Vec2 lo, hi;
};

struct Grid {
  Vec2 origin;
  double cell = 1;
  std::int64_t nx = 1, ny = 1;
  std::int64_t ix(double x) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((x - origin.x) / cell)), 0, nx - 1);
  }
  std::int64_t iy(double y) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((y - origin.y) / cell)), 0, ny - 1);
  }
};

// Calls f(seg) for each segment; pad: per-loop, per-segment half widths added to the boxes
// (empty: none). With `active`: only the segments whose flag is `want`, and of those only
// the ones whose box meets [lo, hi]. A visit, not a list: the inactive segments a search
// looks through are most of the coast (1.5 million at 3 km), copied each time.
template <class F>
void for_each_segment(std::span<const std::vector<Vec2>> loops, std::span<const std::vector<double>> pad,
                      std::span<const std::vector<char>> active, bool want, Vec2 lo, Vec2 hi, F&& f) {
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    const auto& p = loops[l];
    const auto n = static_cast<std::uint32_t>(p.size());
    if (n < 2) continue;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (!active.empty() && (active[l][i] != 0) != want) continue;
      Seg s{p[i], p[(i + 1) % n], l, i, n, {}, {}};
      const double pd = pad.empty() ? 0.0 : 0.5 * pad[l][i];
      s.lo = {std::min(s.a.x, s.b.x) - pd, std::min(s.a.y, s.b.y) - pd};
      s.hi = {std::max(s.a.x, s.b.x) + pd, std::max(s.a.y, s.b.y) + pd};
      if (s.lo.x > hi.x || s.hi.x < lo.x || s.lo.y > hi.y || s.hi.y < lo.y) continue;
      f(s);
    }
  }
}

constexpr Vec2 kNoLow{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
constexpr Vec2 kNoHigh{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};

std::vector<Seg> make_segments(std::span<const std::vector<Vec2>> loops, std::span<const std::vector<double>> pad,
                               std::span<const std::vector<char>> active = {}, bool want = true) {
  std::vector<Seg> segs;
  for_each_segment(loops, pad, active, want, kNoLow, kNoHigh, [&](const Seg& s) { segs.push_back(s); });
  return segs;
}

// The grid for n segments, seg(k) the k-th (its padded box).
template <class At>
Grid make_grid_of(std::size_t n, At&& seg) {
  Grid g;
  Vec2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()}, hi = -lo;
  std::vector<double> len;
  len.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Seg s = seg(k);
    lo = {std::min(lo.x, s.lo.x), std::min(lo.y, s.lo.y)};
    hi = {std::max(hi.x, s.hi.x), std::max(hi.y, s.hi.y)};
    len.push_back(std::max(s.hi.x - s.lo.x, s.hi.y - s.lo.y));
  }
  // Cells about twice the median segment extent: a segment covers a few cells and a cell
  // holds a few segments wherever the coastline is dense.
  std::nth_element(len.begin(), len.begin() + static_cast<long>(len.size() / 2), len.end());
  const double span = std::max(hi.x - lo.x, hi.y - lo.y);
  double cell = std::max(2.0 * len[len.size() / 2], span * 1e-7);
  // Never more than ~16 cells per segment overall (memory bound for sparse data).
  const double min_cell = span / std::sqrt(16.0 * static_cast<double>(n) + 1.0);
  cell = std::max(cell, min_cell);
  if (!(cell > 0)) cell = 1;
  g.origin = lo;
  g.cell = cell;
  g.nx = std::max<std::int64_t>(1, static_cast<std::int64_t>((hi.x - lo.x) / cell) + 1);
  g.ny = std::max<std::int64_t>(1, static_cast<std::int64_t>((hi.y - lo.y) / cell) + 1);
  return g;
}

Grid make_grid(const std::vector<Seg>& segs) {
  return make_grid_of(segs.size(), [&segs](std::size_t k) { return segs[k]; });
}

// Cell entries sorted by cell: the candidate pairs of each cell are tested in order.
std::vector<std::pair<std::int64_t, std::uint32_t>> bin(const std::vector<Seg>& segs, const Grid& g) {
  std::vector<std::pair<std::int64_t, std::uint32_t>> cells;
  cells.reserve(segs.size() * 2);
  for (std::uint32_t k = 0; k < segs.size(); ++k) {
    const Seg& s = segs[k];
    for (std::int64_t y = g.iy(s.lo.y); y <= g.iy(s.hi.y); ++y)
      for (std::int64_t x = g.ix(s.lo.x); x <= g.ix(s.hi.x); ++x) cells.push_back({y * g.nx + x, k});
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

bool adjacent(const Seg& s, const Seg& t) {
  if (s.loop != t.loop) return false;
  return (s.index + 1) % s.n == t.index || (t.index + 1) % t.n == s.index;
}

// Classifies two segments; false when they are disjoint.
bool classify(const Seg& s, const Seg& t, HitKind& kind, Vec2& where) {
  if (adjacent(s, t)) {
    // Consecutive segments share a vertex; they are wrong only when they fold back
    // (collinear, the far end turning back onto the other segment).
    const bool s_first = (s.index + 1) % s.n == t.index;
    const Seg& u = s_first ? s : t;   // u.b == v.a
    const Seg& v = s_first ? t : s;
    if (u.n == 2) return false;
    if (orient2d(u.a, u.b, v.b) == Sign::Zero && dot(u.b - u.a, v.b - v.a) < 0) {
      kind = HitKind::Overlap;
      where = u.b;
      return true;
    }
    return false;
  }
  const SegmentContact c = segment_contact(s.a, s.b, t.a, t.b);
  switch (c.kind) {
    case SegmentContactKind::None:
      return false;
    case SegmentContactKind::Overlap:
      kind = HitKind::Overlap;
      where = 0.5 * (s.a + s.b);
      return true;
    case SegmentContactKind::Touch: {
      kind = HitKind::Touch;
      const Vec2 ends[4] = {s.a, s.b, t.a, t.b};
      where = ends[c.end];
      return true;
    }
    case SegmentContactKind::Cross:
      break;
  }
  kind = HitKind::Cross;
  const Vec2 r = s.b - s.a, q = t.b - t.a;
  const double den = cross(r, q);
  const double u = den != 0 ? cross(t.a - s.a, q) / den : 0.5;
  where = s.a + u * r;
  return true;
}

double seg_distance_point(Vec2 a, Vec2 b, Vec2 p) {
  const Vec2 d = b - a;
  const double l2 = norm2(d);
  double t = l2 > 0 ? dot(p - a, d) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return norm(p - (a + t * d));
}

// The distance of two segments that do not cross: the least of each one's end points' to
// the other (a near miss is measured so by every search).
double near_distance(const Seg& s, const Seg& t) {
  return std::min({seg_distance_point(s.a, s.b, t.a), seg_distance_point(s.a, s.b, t.b),
                   seg_distance_point(t.a, t.b, s.a), seg_distance_point(t.a, t.b, s.b)});
}

// Whether the (padded) boxes of s and t overlap.
bool boxes_meet(const Seg& s, const Seg& t) {
  return !(s.lo.x > t.hi.x || t.lo.x > s.hi.x || s.lo.y > t.hi.y || t.lo.y > s.hi.y);
}

// The one cell a pair is taken in: that of the lower corner of the two boxes' overlap,
// which lies in both boxes and so in a cell each of them covers.
std::int64_t pair_cell(const Grid& g, const Seg& s, const Seg& t) {
  const Vec2 corner{std::max(s.lo.x, t.lo.x), std::max(s.lo.y, t.lo.y)};
  return g.iy(corner.y) * g.nx + g.ix(corner.x);
}

template <class Visit>
void for_each_candidate(const std::vector<Seg>& segs, const Grid& g, IntersectionStats* st, Visit visit) {
  const auto cells = bin(segs, g);
  if (st) st->grid_cells = static_cast<std::size_t>(g.nx * g.ny);
  for (std::size_t i = 0; i < cells.size();) {
    std::size_t j = i;
    while (j < cells.size() && cells[j].first == cells[i].first) ++j;
    const std::int64_t cell = cells[i].first;
    for (std::size_t p = i; p < j; ++p)
      for (std::size_t q = p + 1; q < j; ++q) {
        const Seg& s = segs[cells[p].second];
        const Seg& t = segs[cells[q].second];
        if (!boxes_meet(s, t) || pair_cell(g, s, t) != cell) continue;   // else tested in another cell
        if (st) ++st->candidate_pairs;
        visit(s, t);
      }
    i = j;
  }
}

// The hit of segments s and t, if they meet, recorded with its places in their order.
void record_hit(const Seg& s, const Seg& t, std::vector<SegmentHit>& hits) {
  HitKind kind;
  Vec2 where;
  if (!classify(s, t, kind, where)) return;
  SegmentHit h{s.loop, s.index, t.loop, t.index, kind, where};
  order_places(h);
  hits.push_back(h);
}

// The active segments of the loops of 2 points or more as (loop, index), in that order,
// sized once; `n_all`: those loops' segments, active or not.
std::vector<std::pair<std::uint32_t, std::uint32_t>> active_places(std::span<const std::vector<Vec2>> loops,
                                                                   std::span<const std::vector<char>> active,
                                                                   std::size_t& n_all) {
  std::size_t n_on = 0;
  n_all = 0;
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    if (loops[l].size() < 2) continue;
    n_all += loops[l].size();
    for (const char a : active[l]) n_on += a != 0;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> on;
  on.reserve(n_on);
  for (std::uint32_t l = 0; l < loops.size(); ++l)
    if (loops[l].size() >= 2)
      for (std::uint32_t i = 0; i < loops[l].size(); ++i)
        if (active[l][i]) on.push_back({l, i});
  return on;
}

// The places found (per chunk), in place-pair order (sort_place_pairs), each made into its
// record by make. The segments numbered loop after loop (loop_first, each below 2^32),
// (loop_a, seg_a, loop_b, seg_b) orders as the two numbers do: sorted as one 64-bit key (the
// four-field comparison over 40-byte records cost more). The pairs are distinct, so the
// keys are, and the order is the one sort_place_pairs gives.
template <class P, class Make>
auto in_place_order(std::vector<std::vector<P>>& found, const std::vector<std::size_t>& loop_first, Make make) {
  std::size_t n_found = 0;
  for (const auto& f : found) n_found += f.size();
  std::vector<P> all;
  all.reserve(n_found);
  for (auto& f : found) {
    all.insert(all.end(), f.begin(), f.end());
    std::vector<P>().swap(f);
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const P& x = all[i];
    order[i] = {(std::uint64_t{loop_first[x.loop_a] + x.seg_a} << 32) | (loop_first[x.loop_b] + x.seg_b),
                static_cast<std::uint32_t>(i)};
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<decltype(make(all[0]))> out;
  out.reserve(all.size());
  for (const auto& o : order) out.push_back(make(all[o.second]));
  return out;
}

}  // namespace

std::vector<SegmentHit> find_intersections(std::span<const std::vector<Vec2>> loops, IntersectionStats* stats) {
  std::vector<SegmentHit> hits;
  const std::vector<Seg> segs = make_segments(loops, {});
  if (stats) *stats = {segs.size(), 0, 0};
  if (segs.size() < 2) return hits;
  const Grid g = make_grid(segs);
  for_each_candidate(segs, g, stats, [&hits](const Seg& s, const Seg& t) { record_hit(s, t, hits); });
  sort_place_pairs_on(hits, loops);
  return hits;
}

std::vector<SegmentHit> find_intersections_at(std::span<const std::vector<Vec2>> loops,
                                              std::span<const std::vector<char>> active, int threads) {
  std::vector<SegmentHit> hits;
  const std::vector<Seg> on = make_segments(loops, {}, active, true);   // in (loop, index) order
  if (on.empty()) return hits;
  // Each pair of segments whose boxes overlap and of which one at least is active, once: the
  // grid holds only the active segments; the pairs of two active ones are found as
  // for_each_candidate finds them, and each inactive segment looks in the cells its box
  // covers (an array of offsets: the active grid has at most about 16 cells per active
  // segment, make_grid). A pair is taken only in the cell of the lower corner of the two
  // boxes' overlap, which lies in both boxes and so in a cell each covers; an inactive
  // segment whose box misses the active ones' bounding box meets none of them. The earlier
  // segment in (loop, index) order first, as find_intersections has them (the place a hit is reported at is measured on its first
  // segment), found in fixed chunks whatever the thread count, each chunk's hits in a list
  // of its own, then one list sorted: a pair is taken in one cell only, so the hits are
  // distinct and the sorted list is the same for every count. The repair's rounds ran this
  // on one thread (the segments met by a round's changes are spread over the world, so most
  // of the coast's inactive segments look in the grid each round).
  const Grid g = make_grid(on);
  const auto cells = bin(on, g);
  std::vector<std::uint32_t> start(static_cast<std::size_t>(g.nx * g.ny) + 1, 0);
  for (const auto& c : cells) ++start[static_cast<std::size_t>(c.first) + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  Vec2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()}, hi = -lo;
  for (const Seg& s : on)
    lo = {std::min(lo.x, s.lo.x), std::min(lo.y, s.lo.y)}, hi = {std::max(hi.x, s.hi.x), std::max(hi.y, s.hi.y)};
  std::vector<std::size_t> loop_first(loops.size() + 1, 0);
  for (std::size_t l = 0; l < loops.size(); ++l)
    loop_first[l + 1] = loop_first[l] + (loops[l].size() >= 2 ? loops[l].size() : 0);
  const std::size_t n_all = loop_first.back();
  constexpr std::size_t kEntryChunk = 1 << 14, kSegChunk = 1 << 15;
  const std::size_t n_entry_chunks = (cells.size() + kEntryChunk - 1) / kEntryChunk;
  const std::size_t n_seg_chunks = (n_all + kSegChunk - 1) / kSegChunk;
  std::vector<std::vector<SegmentHit>> found(n_entry_chunks + n_seg_chunks);
  // The pairs of two active segments, by runs of entries (a chunk takes the cells whose
  // first entry it holds), as for_each_candidate takes them.
  parallel_for_chunks(threads, cells.size(), kEntryChunk, [&](std::size_t b, std::size_t e) {
    std::vector<SegmentHit>& mine = found[b / kEntryChunk];
    std::size_t i = b;
    while (i < e && i > 0 && cells[i - 1].first == cells[i].first) ++i;   // a cell begun before
    while (i < e) {
      std::size_t j = i;
      while (j < cells.size() && cells[j].first == cells[i].first) ++j;
      const std::int64_t cell = cells[i].first;
      for (std::size_t p = i; p < j; ++p)
        for (std::size_t q = p + 1; q < j; ++q) {
          const Seg& s = on[cells[p].second];
          const Seg& t = on[cells[q].second];
          if (!boxes_meet(s, t) || pair_cell(g, s, t) != cell) continue;   // else tested in another cell
          record_hit(s, t, mine);
        }
      i = j;
    }
  });
  // Then each inactive segment whose box meets the active ones' bounding box looks in the
  // cells its box covers, by runs of the loops' segments (numbered loop after loop).
  parallel_for_chunks(threads, n_all, kSegChunk, [&](std::size_t b, std::size_t e) {
    std::vector<SegmentHit>& mine = found[n_entry_chunks + b / kSegChunk];
    auto l = static_cast<std::uint32_t>(std::upper_bound(loop_first.begin(), loop_first.end(), b) - loop_first.begin() - 1);
    for (std::size_t k = b; k < e; ++k) {
      while (k >= loop_first[l + 1]) ++l;
      const auto i = static_cast<std::uint32_t>(k - loop_first[l]);
      if (active[l][i]) continue;
      const auto& p = loops[l];
      const auto n = static_cast<std::uint32_t>(p.size());
      Seg t{p[i], p[(i + 1) % n], l, i, n, {}, {}};
      t.lo = {std::min(t.a.x, t.b.x), std::min(t.a.y, t.b.y)};
      t.hi = {std::max(t.a.x, t.b.x), std::max(t.a.y, t.b.y)};
      if (t.lo.x > hi.x || t.hi.x < lo.x || t.lo.y > hi.y || t.hi.y < lo.y) continue;
      for (std::int64_t y = g.iy(t.lo.y); y <= g.iy(t.hi.y); ++y)
        for (std::int64_t x = g.ix(t.lo.x); x <= g.ix(t.hi.x); ++x) {
          const std::int64_t cell = y * g.nx + x;
          const auto c = static_cast<std::size_t>(cell);
          for (std::uint32_t en = start[c]; en < start[c + 1]; ++en) {
            const Seg& s = on[cells[en].second];
            if (!boxes_meet(s, t) || pair_cell(g, s, t) != cell) continue;   // else taken in another cell
            if (std::pair(s.loop, s.index) < std::pair(t.loop, t.index))
              record_hit(s, t, mine);
            else
              record_hit(t, s, mine);
          }
        }
    }
  });
  std::size_t n_hits = 0;
  for (const auto& f : found) n_hits += f.size();
  hits.reserve(n_hits);
  for (const auto& f : found) hits.insert(hits.end(), f.begin(), f.end());
  sort_place_pairs_on(hits, loops);
  return hits;
}

std::vector<NearMiss> find_near_misses(std::span<const std::vector<Vec2>> loops,
                                       std::span<const std::vector<double>> width) {
  std::vector<NearMiss> out;
  std::vector<Seg> segs = make_segments(loops, width);
  if (segs.size() < 2) return out;
  const Grid g = make_grid(segs);
  for_each_candidate(segs, g, nullptr, [&](const Seg& s, const Seg& t) {
    if (s.loop == t.loop) {
      // Within one loop only far-apart parts count: at least 3 segments away both ways.
      const std::uint32_t d = s.index > t.index ? s.index - t.index : t.index - s.index;
      if (std::min(d, s.n - d) < 3) return;
    }
    const double w = std::min(width[s.loop][s.index], width[t.loop][t.index]);
    const double d = near_distance(s, t);
    if (d >= w || d == 0) return;
    out.push_back({s.loop, s.index, t.loop, t.index, d, 0.5 * (s.a + t.a)});
  });
  sort_place_pairs_on(out, loops);
  return out;
}

std::vector<NearMiss> find_near_pairs(std::span<const std::vector<Vec2>> loops,
                                      std::span<const std::vector<double>> width,
                                      std::span<const std::vector<char>> active, std::size_t* searched, int threads) {
  std::vector<NearMiss> out;
  // The active segments as (loop, index), in that order; a segment's points and padded box
  // are read from the loops where a test needs them (a Seg copy of each, 80 bytes, and two
  // sorted (cell, segment) lists of 16 bytes an entry were most of passage closing's first
  // round at 3 km on the full GSHHG, the import's peak: docs/kernel.md).
  std::size_t n_all = 0;
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> on = active_places(loops, active, n_all);
  if (searched) *searched = on.size();
  if (on.empty()) return out;
  auto seg_at = [&](std::uint32_t l, std::uint32_t i) {
    const auto& p = loops[l];
    const auto n = static_cast<std::uint32_t>(p.size());
    Seg s{p[i], p[(i + 1) % n], l, i, n, {}, {}};
    const double pd = 0.5 * width[l][i];
    s.lo = {std::min(s.a.x, s.b.x) - pd, std::min(s.a.y, s.b.y) - pd};
    s.hi = {std::max(s.a.x, s.b.x) + pd, std::max(s.a.y, s.b.y) + pd};
    return s;
  };
  auto on_seg = [&](std::size_t k) { return seg_at(on[k].first, on[k].second); };
  const Grid g = make_grid_of(on.size(), on_seg);
  // The cells' entries (cell, active segment), sorted: each cell's in (loop, index) order.
  // Most cells of a world's grid are empty (up to 16 a segment, make_grid_of): an offsets
  // array over all of them (4 bytes a cell, 21 MB for the 323,000 segments of the first
  // closing round at 3 km) is made only where the cells are few, else a cell's entries are
  // found by a binary search.
  const auto n_cells = static_cast<std::size_t>(g.nx * g.ny);
  SM_ASSERT(n_cells < 0xFFFFFFFFu, "find_near_pairs: more cells than 32-bit cell numbers (coast/intersections.cpp)");
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;
  std::size_t n_entries = 0;
  for (std::size_t k = 0; k < on.size(); ++k) {
    const Seg s = on_seg(k);
    n_entries += static_cast<std::size_t>((g.iy(s.hi.y) - g.iy(s.lo.y) + 1) * (g.ix(s.hi.x) - g.ix(s.lo.x) + 1));
  }
  auto each_entry = [&](auto&& f) {
    for (std::size_t k = 0; k < on.size(); ++k) {
      const Seg s = on_seg(k);
      for (std::int64_t y = g.iy(s.lo.y); y <= g.iy(s.hi.y); ++y)
        for (std::int64_t x = g.ix(s.lo.x); x <= g.ix(s.hi.x); ++x)
          f(static_cast<std::uint32_t>(y * g.nx + x), static_cast<std::uint32_t>(k));
    }
  };
  std::vector<std::uint32_t> start;
  if (n_cells <= 4 * n_entries) {
    // Placed by counting, in the order made (each cell's in segment order): the order the
    // sort below gives, without the sort (most of a round's grid).
    start.assign(n_cells + 1, 0);
    each_entry([&](std::uint32_t c, std::uint32_t) { ++start[c + 1]; });
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    entries.resize(n_entries);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    each_entry([&](std::uint32_t c, std::uint32_t k) { entries[fill[c]++] = {c, k}; });
  } else {
    entries.reserve(n_entries);
    each_entry([&](std::uint32_t c, std::uint32_t k) { entries.push_back({c, k}); });
    std::sort(entries.begin(), entries.end());
  }
  // The entries of cell c: [first, second) in `entries`.
  auto cell_range = [&](std::size_t c) -> std::pair<std::size_t, std::size_t> {
    if (!start.empty()) return {start[c], start[c + 1]};
    const auto key = static_cast<std::uint32_t>(c);
    const auto lo_it = std::lower_bound(entries.begin(), entries.end(), key, [](const auto& en, std::uint32_t v) { return en.first < v; });
    auto hi_it = lo_it;
    while (hi_it != entries.end() && hi_it->first == key) ++hi_it;
    return {static_cast<std::size_t>(lo_it - entries.begin()), static_cast<std::size_t>(hi_it - entries.begin())};
  };
  // The active segments' boxes' bounding box: the grid's, which starts at its lower corner.
  const Vec2 lo = g.origin, hi = g.origin + Vec2{static_cast<double>(g.nx) * g.cell, static_cast<double>(g.ny) * g.cell};
  // The pairs as find_near_misses takes them: s before t in (loop, index) order. A chunk
  // lists its pairs' places only (16 bytes, where a record is 40); the records are made
  // once all are found, the distance measured again by the same expression (the same bits).
  struct Places {
    std::uint32_t loop_a, seg_a, loop_b, seg_b;
  };
  auto test = [&](const Seg& s, const Seg& t, std::vector<Places>& found) {
    const double w = std::min(width[s.loop][s.index], width[t.loop][t.index]);
    const double d = near_distance(s, t);
    if (d >= w || d == 0) return;
    found.push_back({s.loop, s.index, t.loop, t.index});
  };
  // Work in fixed chunks whatever the thread count (each chunk's pairs in a list of its
  // own), then one list sorted: the pairs are distinct (a pair is taken in one cell, as in
  // find_intersections_at), so the sorted list is the same for every count.
  // First the pairs of two active segments, by runs of entries (a chunk takes the cells
  // whose first entry it holds).
  constexpr std::size_t kEntryChunk = 1 << 14, kSegChunk = 1 << 14;
  const std::size_t n_entry_chunks = (entries.size() + kEntryChunk - 1) / kEntryChunk;
  const std::size_t n_seg_chunks = (n_all + kSegChunk - 1) / kSegChunk;
  std::vector<std::vector<Places>> found(n_entry_chunks + n_seg_chunks);
  parallel_for_chunks(threads, entries.size(), kEntryChunk, [&](std::size_t b, std::size_t e) {
    std::vector<Places>& mine = found[b / kEntryChunk];
    std::vector<Seg> here;
    std::size_t i = b;
    while (i < e && i > 0 && entries[i - 1].first == entries[i].first) ++i;   // a cell begun before
    while (i < e) {
      const std::uint32_t c = entries[i].first;
      here.clear();
      for (; i < entries.size() && entries[i].first == c; ++i) here.push_back(on_seg(entries[i].second));
      for (std::size_t p = 0; p < here.size(); ++p)
        for (std::size_t q = p + 1; q < here.size(); ++q)
          if (boxes_meet(here[p], here[q]) && pair_cell(g, here[p], here[q]) == c) test(here[p], here[q], mine);
    }
  });
  // Then each inactive segment whose box meets the active ones' bounding box looks in the
  // cells its box covers, by runs of the loops' segments (numbered loop after loop).
  std::vector<std::size_t> loop_first(loops.size() + 1, 0);
  for (std::size_t l = 0; l < loops.size(); ++l) loop_first[l + 1] = loop_first[l] + (loops[l].size() >= 2 ? loops[l].size() : 0);
  parallel_for_chunks(threads, n_all, kSegChunk, [&](std::size_t b, std::size_t e) {
    std::vector<Places>& mine = found[n_entry_chunks + b / kSegChunk];
    auto l = static_cast<std::uint32_t>(std::upper_bound(loop_first.begin(), loop_first.end(), b) - loop_first.begin() - 1);
    for (std::size_t k = b; k < e; ++k) {
      while (k >= loop_first[l + 1]) ++l;
      const auto i = static_cast<std::uint32_t>(k - loop_first[l]);
      if (active[l][i]) continue;
      const Seg t = seg_at(l, i);
      if (t.lo.x > hi.x || t.hi.x < lo.x || t.lo.y > hi.y || t.hi.y < lo.y) continue;
      for (std::int64_t y = g.iy(t.lo.y); y <= g.iy(t.hi.y); ++y)
        for (std::int64_t x = g.ix(t.lo.x); x <= g.ix(t.hi.x); ++x) {
          const auto c = static_cast<std::size_t>(y * g.nx + x);
          const auto [first, last] = cell_range(c);
          for (std::size_t en = first; en < last; ++en) {
            const Seg s = on_seg(entries[en].second);
            // Else taken in another cell.
            if (!boxes_meet(s, t) || pair_cell(g, s, t) != static_cast<std::int64_t>(c)) continue;
            if (std::pair(s.loop, s.index) < std::pair(t.loop, t.index))
              test(s, t, mine);
            else
              test(t, s, mine);
          }
        }
    }
  });
  std::vector<std::pair<std::uint32_t, std::uint32_t>>().swap(entries);
  std::vector<std::uint32_t>().swap(start);
  SM_ASSERT(n_all < 0xFFFFFFFFu, "find_near_pairs: more segments than 32-bit numbers (coast/intersections.cpp)");
  return in_place_order(found, loop_first, [&](const Places& x) {
    const Seg s = seg_at(x.loop_a, x.seg_a), t = seg_at(x.loop_b, x.seg_b);
    return NearMiss{x.loop_a, x.seg_a, x.loop_b, x.seg_b, near_distance(s, t), 0.5 * (s.a + t.a)};
  });
}

std::vector<NearMiss> find_near_misses_again(std::span<const std::vector<Vec2>> loops,
                                             std::span<const std::vector<double>> width,
                                             std::span<const std::vector<char>> active, std::vector<NearMiss> before,
                                             int threads) {
  // Within one loop only far-apart parts count: at least 3 segments away both ways.
  auto near_along = [&](const NearMiss& m) {
    if (m.loop_a != m.loop_b) return false;
    const auto n = static_cast<std::uint32_t>(loops[m.loop_a].size());
    const std::uint32_t d = m.seg_a > m.seg_b ? m.seg_a - m.seg_b : m.seg_b - m.seg_a;
    return std::min(d, n - d) < 3;
  };
  // A place past its loop's end names a segment that is gone: dropped as an active one.
  auto searched = [&](std::uint32_t l, std::uint32_t s) { return s >= active[l].size() || active[l][s]; };
  std::erase_if(before, [&](const NearMiss& m) {
    return searched(m.loop_a, m.seg_a) || searched(m.loop_b, m.seg_b) || near_along(m);
  });
  // Sorted already when renumber_for_joins kept the order (each record's places unique then:
  // the only two that can meet, a replaced segment's, are at a bridge, searched again).
  if (!std::is_sorted(before.begin(), before.end(),
                      [](const NearMiss& a, const NearMiss& b) { return place_pair_key(a) < place_pair_key(b); }))
    sort_place_pairs_on(before, loops);
  std::vector<NearMiss> found = find_near_pairs(loops, width, active, nullptr, threads);
  std::erase_if(found, near_along);
  std::vector<NearMiss> out;
  out.reserve(before.size() + found.size());
  std::merge(before.begin(), before.end(), found.begin(), found.end(), std::back_inserter(out),
             [](const NearMiss& a, const NearMiss& b) { return place_pair_key(a) < place_pair_key(b); });
  return out;
}

void renumber_for_joins(std::span<const LoopJoin> joins, std::vector<NearMiss>& near,
                        std::vector<std::vector<char>>& active) {
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::uint32_t loops = 0;
  for (const LoopJoin& j : joins) loops = std::max({loops, j.into + 1, j.from + 1});
  std::vector<std::uint32_t> join_of(loops, kNone);
  for (std::uint32_t i = 0; i < joins.size(); ++i) join_of[joins[i].into] = join_of[joins[i].from] = i;
  // A joined segment keeps its points and its start point's width; the replaced ones are
  // numbered as the bridges that replace them (searched again).
  auto place = [&](std::uint32_t& l, std::uint32_t& s) {
    if (l >= loops || join_of[l] == kNone) return;
    const LoopJoin& j = joins[join_of[l]];
    if (l == j.into) {
      s = s == j.k_into ? j.n_into - 1 : (s + j.n_into - j.k_into - 1) % j.n_into;
    } else {
      s = j.n_into + (s == j.k_from ? j.n_from - 1 : (s + j.n_from - j.k_from - 1) % j.n_from);
      l = j.into;
    }
  };
  // The records of loops in no join keep their places, so their order: a list sorted before
  // stays sorted with the renumbered records sorted on their own and merged in, and
  // find_near_misses_again need not sort it (the straits' passes at 3 km: 290,000 records
  // sorted each pass, a few thousand of them renumbered).
  auto by_key = [](const NearMiss& a, const NearMiss& b) { return place_pair_key(a) < place_pair_key(b); };
  const bool was_sorted = std::is_sorted(near.begin(), near.end(), by_key);
  auto joined = [&](std::uint32_t l) { return l < loops && join_of[l] != kNone; };
  std::vector<NearMiss> renumbered;
  for (NearMiss& m : near) {
    const bool moves = joined(m.loop_a) || joined(m.loop_b);
    place(m.loop_a, m.seg_a);
    place(m.loop_b, m.seg_b);
    order_places(m);   // the distance and the place (a half sum) do not depend on the order
    if (was_sorted && moves) renumbered.push_back(m);
  }
  if (was_sorted && !renumbered.empty()) {
    std::erase_if(near, [&](const NearMiss& m) { return joined(m.loop_a) || joined(m.loop_b); });
    sort_place_pairs_by_keys(renumbered);   // distinct: the places map one to one
    std::vector<NearMiss> merged;
    merged.reserve(near.size() + renumbered.size());
    std::merge(near.begin(), near.end(), renumbered.begin(), renumbered.end(), std::back_inserter(merged), by_key);
    near = std::move(merged);
  }
  for (const LoopJoin& j : joins) {
    const std::uint32_t n = j.n_into + j.n_from;
    std::vector<char>& a = active[j.into];
    for (const std::uint32_t bridge : {j.n_into - 1, n - 1})
      for (std::uint32_t d = 0; d < 5; ++d) a[(bridge + n - 2 + d) % n] = 1;
  }
}

}  // namespace sm::coast
