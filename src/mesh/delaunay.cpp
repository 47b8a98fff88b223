// Bowyer-Watson Delaunay insertion with ghost triangles.
//
// Ghost triangles join every hull edge to one symbolic vertex at infinity,
// so every side has a twin and a point outside the hull is located like any
// other: the ghost (u, v, G) across hull edge u -> v "contains" p when p is
// strictly left of u -> v, or on the open segment uv. We use ghosts rather
// than a big enclosing triangle because the enclosing triangle's finite
// corners change which hull edges are Delaunay (near-collinear hull points
// end up joined to them) unless it is pushed impossibly far; ghosts keep the
// result exactly the Delaunay triangulation of the input.
#include "mesh/delaunay.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <new>
#include <utility>

#include "base/check.h"
#include "base/huge_alloc.h"
#include "base/rng.h"
#include "mesh/cavity.h"
#include "mesh/locate.h"

namespace sm {
namespace {

constexpr std::uint32_t kGhost = 0xFFFFFFFEu;

// Hilbert curve order as a 4-state machine. The state is the transform
// (swap of x and y, complement of both) accumulated by the quadrants above;
// each level reads one bit of x and y, emits a 2-bit digit and updates the
// state. The table below runs four levels per lookup: index
// state << 8 | x4 << 4 | y4, value digits8 << 2 | new state.
constexpr std::array<std::uint16_t, 1024> make_hilbert_table() {
  std::array<std::uint16_t, 1024> tab{};
  for (std::uint32_t st = 0; st < 4; ++st)
    for (std::uint32_t x4 = 0; x4 < 16; ++x4)
      for (std::uint32_t y4 = 0; y4 < 16; ++y4) {
        std::uint32_t comp = st & 1, swp = st >> 1, d = 0;
        for (int l = 3; l >= 0; --l) {
          std::uint32_t ex = ((x4 >> l) & 1) ^ comp, ey = ((y4 >> l) & 1) ^ comp;
          if (swp) {
            const std::uint32_t t = ex;
            ex = ey;
            ey = t;
          }
          d = d << 2 | ((3 * ex) ^ ey);
          // Quadrants with y = 0 are entered rotated: swap, plus complement
          // when x = 1 (the lower-left / lower-right cells of the U).
          if (ey == 0) {
            comp ^= ex;
            swp ^= 1;
          }
        }
        tab[st << 8 | x4 << 4 | y4] = static_cast<std::uint16_t>(d << 2 | swp << 1 | comp);
      }
  return tab;
}
constexpr std::array<std::uint16_t, 1024> kHilbert = make_hilbert_table();

// Sorts (key << 32 | index) values by the low key_bits (at most 33) of the
// key: LSD radix, passes of 11 bits, stable. One read counts the digits of
// every pass.
void radix_sort_keys(std::vector<std::uint64_t>& v, int key_bits) {
  const int passes = (key_bits + 10) / 11;
  SM_ASSERT(passes <= 3, "radix_sort_keys: key wider than 33 bits");
  std::vector<std::size_t> count(3 * 2049, 0);
  for (std::uint64_t x : v)
    for (int d = 0; d < passes; ++d) ++count[2049 * d + ((x >> (32 + 11 * d)) & 0x7FF) + 1];
  std::vector<std::uint64_t> tmp(v.size());
  for (int d = 0; d < passes; ++d) {
    std::size_t* c = &count[2049 * d];
    for (int i = 0; i < 2048; ++i) c[i + 1] += c[i];
    const int shift = 32 + 11 * d;
    for (std::uint64_t x : v) tmp[c[(x >> shift) & 0x7FF]++] = x;
    v.swap(tmp);
  }
}

// Working triangle: corners (kGhost allowed), neighbour sides and the
// cavity stamp in one half cache line, so a conflict test or a walk step
// touches one line. Sides are numbered 4t + e here (shifts, no division by
// 3) and become 3t + e in the store.
struct alignas(32) Tri {
  std::uint32_t v[3];
  std::uint32_t n[3];
  std::uint32_t stamp;
  std::uint32_t ghost;  // 1 when a corner is the vertex at infinity
};

class Builder {
 public:
  Builder(TriangleStore& m, const DelaunayOptions& opt, DelaunayResult& res)
      : m_(m), res_(res), stats_(&res.stats.predicates), rng_(opt.seed), seed_(opt.seed) {}

  void run();

 private:
  static bool is_ghost(const Tri& t) { return t.ghost != 0; }
  // The next cavity test or walk step reads one of these; the triangles of a
  // neighbourhood were made in different BRIO rounds, so they lie far apart
  // in memory and each read is a cache miss. Issuing all three at once lets
  // the misses overlap instead of queueing behind the predicate branches.
  void prefetch_neighbours(const Tri& t) const {
    for (std::uint32_t e = 0; e < 3; ++e) __builtin_prefetch(&tri_[t.n[e] >> 2]);
  }
  Vec2 pos(std::uint32_t v) const { return pts_[v]; }
  bool in_conflict(const Tri& t, std::uint32_t p) const;
  std::uint32_t locate(std::uint32_t p, std::uint32_t start);
  void insert(std::uint32_t p, std::uint32_t t0);
  std::uint32_t new_slot() {
    tri_.push_back(Tri{});
    return static_cast<std::uint32_t>(tri_.size() - 1);
  }
  void link(std::uint32_t a, std::uint32_t b) {
    tri_[a >> 2].n[a & 3] = b;
    tri_[b >> 2].n[b & 3] = a;
  }
  void finish();

  TriangleStore& m_;
  DelaunayResult& res_;
  PredicateStats* stats_;
  Rng rng_;
  std::uint64_t seed_;
  // Vertices are renumbered by insertion rank so that consecutive insertions
  // touch neighbouring memory: pts_[k] = m.xy[orig_[k]]. Ties are still
  // broken by the original ids, so the result does not depend on the order.
  std::vector<Vec2, HugeAlloc<Vec2>> pts_;
  std::vector<std::uint32_t> orig_;
  std::vector<Tri, HugeAlloc<Tri>> tri_;
  std::uint32_t stamp_now_ = 0;
  std::uint32_t last_ = 0;  // a real triangle near the last insertion
  // The ghost written last. Only an insertion whose cavity holds ghosts
  // rewrites ghost slots, and it writes new ghosts, so this stays a ghost.
  std::uint32_t ghost_hint_ = 0;
  // Scratch, reused by every insertion.
  struct Bound {
    std::uint32_t a, b, outer;
  };
  std::vector<std::uint32_t> stack_, cavity_, vmap_;
  std::vector<Bound> bound_;
};

// inline: with the cavity search a template (mesh/cavity.h), GCC stopped inlining this
// test into insert(), a call per neighbour tested that cost the construction 3%.
inline bool Builder::in_conflict(const Tri& t, std::uint32_t p) const {
  const std::uint32_t* c = t.v;
  if (!t.ghost) {
    const Sign s = incircle(pos(c[0]), pos(c[1]), pos(c[2]), pos(p), stats_);
    if (s != Sign::Zero) return s == Sign::Positive;
    return incircle_sos_tie(pos(c[0]), pos(c[1]), pos(c[2]), pos(p), orig_[c[0]], orig_[c[1]], orig_[c[2]],
                            orig_[p], stats_) == Sign::Positive;
  }
  std::uint32_t u, v;
  if (c[2] == kGhost) u = c[0], v = c[1];
  else if (c[0] == kGhost) u = c[1], v = c[2];
  else u = c[2], v = c[0];
  const Vec2 a = pos(u), b = pos(v), q = pos(p);
  const Sign o = orient2d(a, b, q, stats_);
  if (o != Sign::Zero) return o == Sign::Positive;
  // Collinear: in conflict only on the open segment (exact comparisons).
  if (a.x != b.x) return (a.x < q.x && q.x < b.x) || (b.x < q.x && q.x < a.x);
  return (a.y < q.y && q.y < b.y) || (b.y < q.y && q.y < a.y);
}

// Visibility walk (mesh/locate.h) from a real triangle: cross a side that has p strictly
// on its right, skipping the side we came through. Stops in a real triangle containing p
// (closed) or in the ghost beyond the hull side crossed. Side order: the first triangle
// starts at a random side (fixed seed); after that the two remaining sides are tried in
// rotation order, which is cheaper (no random branch per step) and terminates because the
// triangulation is Delaunay at every walk (Edelsbrunner's acyclicity of the in-front
// relation: no triangle is entered twice, so the walk stays within the triangle count).
// Should a walk ever exceed 4096 steps it switches to a random side order per step, whose
// termination does not rely on that property; past the triangle count, a scan.
std::uint32_t Builder::locate(std::uint32_t p, std::uint32_t t) {
  static constexpr std::uint32_t kNext[3] = {1, 2, 0};
  struct Walker {
    Builder& b;
    std::uint32_t came = 3;  // local index of the side we entered by; 3 = none
    std::uint32_t first_side(std::uint32_t tri, std::uint64_t step) {
      b.prefetch_neighbours(b.tri_[tri]);
      if (step == 0 || step > 4096) return b.rng_.below3();
      return kNext[came];
    }
    bool skip(std::uint32_t e) const { return e == came; }
    Vec2 org(std::uint32_t tri, std::uint32_t e) const { return b.pos(b.tri_[tri].v[e]); }
    Vec2 dest(std::uint32_t tri, std::uint32_t e) const { return b.pos(b.tri_[tri].v[kNext[e]]); }
    PredicateStats* predicate_stats() const { return b.stats_; }
    AcrossStep across(std::uint32_t tri, std::uint32_t e) {
      const std::uint32_t o = b.tri_[tri].n[e];
      came = o & 3;
      return {is_ghost(b.tri_[o >> 2]) ? Across::EnterAndStop : Across::Enter, o >> 2};
    }
  } w{*this};
  const Vec2 q = pos(p);
  const WalkResult r = walk_to(w, q, t, tri_.size());
  res_.stats.walk_steps += r.steps;
  if (r.end == WalkEnd::Found) return r.tri;
  // Every slot of tri_ is a live triangle (cavities reuse theirs): the first real one that
  // holds p, else a ghost in conflict with it (p beyond its hull side).
  for (std::uint32_t k = 0; k < tri_.size(); ++k)
    if (!is_ghost(tri_[k]) && walker_contains(w, k, q)) return k;
  for (std::uint32_t k = 0; k < tri_.size(); ++k)
    if (is_ghost(tri_[k]) && in_conflict(tri_[k], p)) return k;
  SM_ASSERT(false, "delaunay: no triangle holds the point");
  return t;
}

void Builder::insert(std::uint32_t p, std::uint32_t t0) {
  // The cavity (mesh/cavity.h) over the working triangles: visited ones carry this
  // insertion's stamp; every side has a twin (ghosts beyond the hull).
  struct Host {
    Builder& b;
    std::uint32_t point, stamp;
    void start(std::uint32_t first) {
      b.tri_[first].stamp = stamp;
      b.prefetch_neighbours(b.tri_[first]);
    }
    bool neighbour(std::uint32_t t, std::uint32_t e, std::uint32_t& nt) const {
      nt = b.tri_[t].n[e] >> 2;
      return true;
    }
    bool visited(std::uint32_t nt) const { return b.tri_[nt].stamp == stamp; }
    bool in_conflict(std::uint32_t nt) const { return b.in_conflict(b.tri_[nt], point); }
    void visit(std::uint32_t nt) {
      b.tri_[nt].stamp = stamp;
      b.prefetch_neighbours(b.tri_[nt]);
    }
    void boundary(std::uint32_t t, std::uint32_t e) {
      const Tri& tr = b.tri_[t];
      b.bound_.push_back({tr.v[e], tr.v[e == 2 ? 0 : e + 1], tr.n[e]});
    }
  } host{*this, p, ++stamp_now_};
  bound_.clear();
  cavity_search(host, t0, stack_, cavity_);
  res_.stats.cavity_triangles += cavity_.size();
  // The boundary is a simple polygon around p: one new triangle (a, b, p)
  // per boundary edge, two more triangles than the cavity had.
  while (cavity_.size() < bound_.size()) cavity_.push_back(new_slot());
  const std::size_t k = bound_.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Bound& bd = bound_[i];
    Tri& t = tri_[cavity_[i]];
    t.v[0] = bd.a, t.v[1] = bd.b, t.v[2] = p;
    t.ghost = bd.a == kGhost || bd.b == kGhost;
    if (t.ghost) ghost_hint_ = cavity_[i];
    link(cavity_[i] << 2, bd.outer);
  }
  // Link side b -> p of the triangle on edge (a, b) with side p -> b of the
  // one on (b, c).
  const auto n = static_cast<std::uint32_t>(pts_.size());
  const bool closed = fan_pairs(
      bound_, [n](std::uint32_t v) { return v == kGhost ? n : v; }, std::size_t{n} + 1, vmap_,
      [this](std::size_t i, std::size_t j) { link(cavity_[i] << 2 | 1, cavity_[j] << 2 | 2); });
  SM_ASSERT(closed, "delaunay: the cavity boundary does not close");
  // Start the next walk from the new triangle that faces the next point
  // (points are numbered in insertion order). A heuristic with inexact
  // arithmetic: it only picks where the exact walk starts.
  const Vec2 pp = pos(p), dq = p + 1 < pts_.size() ? pos(p + 1) - pp : Vec2{};
  // (Scores may overflow near the double range: the first real triangle
  // stands unless a score is strictly better.)
  bool have = false;
  double best = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const Bound& bd = bound_[i];
    if (bd.a == kGhost || bd.b == kGhost) continue;
    const double score = dot(0.5 * pos(bd.a) + 0.5 * pos(bd.b) - pp, dq);
    // Selects rather than branches: which edge wins is unpredictable.
    const bool better = !have || score > best;
    best = better ? score : best;
    last_ = better ? cavity_[i] : last_;
    have = true;
  }
}

void Builder::run() {
  const auto n = m_.num_vertices();
  orig_ = brio_order(m_.xy, seed_);
  pts_.resize(n);
  for (std::uint32_t k = 0; k < n; ++k) pts_[k] = m_.xy[orig_[k]];
  // Initial triangle: the first three points in order that are not collinear.
  std::uint32_t i0 = n == 0 ? kNoIndex : 0, i1 = kNoIndex, i2 = kNoIndex;
  for (std::uint32_t k = 1; k < n && i1 == kNoIndex; ++k)
    if (!(pos(k) == pos(i0))) i1 = k;
  for (std::uint32_t k = i1 + 1; k < n && i1 != kNoIndex && i2 == kNoIndex; ++k)
    if (orient2d(pos(i0), pos(i1), pos(k), stats_) != Sign::Zero) i2 = k;
  if (i2 == kNoIndex) {
    res_.error = n < 3 ? "fewer than three points to triangulate" : "all points are collinear or coincident";
    return;
  }
  if (orient2d(pos(i0), pos(i1), pos(i2), stats_) == Sign::Negative) std::swap(i1, i2);
  tri_.reserve(2 * std::size_t{n} + 4);
  const std::uint32_t c[3] = {i0, i1, i2};
  const std::uint32_t t = new_slot();
  for (int e = 0; e < 3; ++e) tri_[t].v[e] = c[e];
  std::uint32_t gh[3];
  for (std::uint32_t e = 0; e < 3; ++e) {
    gh[e] = new_slot();  // ghost across edge c[e] -> c[e+1]: (c[e+1], c[e], G)
    tri_[gh[e]].v[0] = c[(e + 1) % 3], tri_[gh[e]].v[1] = c[e], tri_[gh[e]].v[2] = kGhost;
    tri_[gh[e]].ghost = 1;
    link(t << 2 | e, gh[e] << 2);
  }
  for (int e = 0; e < 3; ++e) link(gh[e] << 2 | 1, gh[(e + 2) % 3] << 2 | 2);
  last_ = t;
  ghost_hint_ = gh[0];
  for (std::uint32_t p = 0; p < n; ++p) {
    if (p == i0 || p == i1 || p == i2) continue;
    const std::uint32_t t0 = locate(p, last_);
    if (!is_ghost(tri_[t0])) {
      const std::uint32_t* tc = tri_[t0].v;
      const Vec2 q = pos(p);
      std::uint32_t same = kNoIndex;
      for (int e = 0; e < 3; ++e)
        if (pos(tc[e]) == q) same = tc[e];
      if (same != kNoIndex) {
        res_.duplicates.push_back({VertexId{orig_[p]}, VertexId{orig_[same]}});
        continue;
      }
    }
    insert(p, t0);
  }
  finish();
}

// Drops the ghosts and writes the real triangles into the store. The few
// ghosts (one per hull edge) are found by walking their ring from one of
// them (not by reading every slot), unlinked from their real neighbours, then
// the last real triangles move into the ghosts' low slots, so the final pass
// is one streaming copy without an id map (deterministic: it depends only on
// the slot layout).
void Builder::finish() {
  const auto slots = static_cast<std::uint32_t>(tri_.size());
  std::vector<std::uint32_t> ghosts;
  SM_ASSERT(is_ghost(tri_[ghost_hint_]), "delaunay: the ghost hint is not a ghost");
  const std::uint32_t seen = ++stamp_now_;
  tri_[ghost_hint_].stamp = seen;
  ghosts.push_back(ghost_hint_);
  for (std::size_t i = 0; i < ghosts.size(); ++i)
    for (std::uint32_t e = 0; e < 3; ++e) {
      Tri& o = tri_[tri_[ghosts[i]].n[e] >> 2];
      if (is_ghost(o) && o.stamp != seen) {
        o.stamp = seen;
        ghosts.push_back(tri_[ghosts[i]].n[e] >> 2);
      }
    }
  // Ascending slots: the moves below fill the lowest ghost slots first.
  std::sort(ghosts.begin(), ghosts.end());
  for (std::uint32_t g : ghosts)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t o = tri_[g].n[e];
      if (!is_ghost(tri_[o >> 2])) tri_[o >> 2].n[o & 3] = kNoIndex;
    }
  const std::uint32_t nt = slots - static_cast<std::uint32_t>(ghosts.size());
  std::uint32_t mover = slots;
  for (std::uint32_t g : ghosts) {
    if (g >= nt) break;
    do --mover;
    while (is_ghost(tri_[mover]));
    tri_[g] = tri_[mover];
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t o = tri_[g].n[e];
      if (o != kNoIndex) tri_[o >> 2].n[o & 3] = g << 2 | e;
    }
  }
  m_.corner.resize(3 * std::size_t{nt});
  m_.twin.resize(3 * std::size_t{nt});
  m_.side_flags.assign(3 * std::size_t{nt}, 0);
  m_.tri_flags.assign(nt, 0);
  m_.free_tris.clear();
  // out_side by insertion rank first (sequential writes), then scattered once.
  std::vector<Side> out_local(pts_.size());
  for (std::uint32_t t = 0; t < nt; ++t) {
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t o = tri_[t].n[e];
      const std::uint32_t k = tri_[t].v[e];
      m_.corner[3 * t + e] = VertexId{orig_[k]};
      m_.twin[3 * t + e] = o == kNoIndex ? Side{} : Side{3 * (o >> 2) + (o & 3)};
      out_local[k] = Side{3 * t + e};
    }
  }
  m_.out_side.assign(m_.num_vertices(), Side{});
  for (std::uint32_t k = 0; k < pts_.size(); ++k) m_.out_side[orig_[k]] = out_local[k];
}

}  // namespace

// Position along a Hilbert curve of a point on a 2^bits x 2^bits grid
// (bits a multiple of 4).
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits) {
  std::uint32_t d = 0, st = 0;
  for (int l = bits - 4; l >= 0; l -= 4) {
    const std::uint32_t v = kHilbert[st << 8 | ((x >> l) & 15) << 4 | ((y >> l) & 15)];
    d = d << 8 | v >> 2;
    st = v & 3;
  }
  return d;
}

std::vector<std::uint32_t> brio_order(const std::vector<Vec2>& xy, std::uint64_t seed) {
  const auto n = static_cast<std::uint32_t>(xy.size());
  std::vector<std::uint32_t> order(n);
  if (n == 0) return order;
  double x0 = xy[0].x, x1 = x0, y0 = xy[0].y, y1 = y0;
  for (const Vec2& p : xy) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  // A grid finer than the point spacing is enough to order by; 12 bits per
  // axis plus 4 round bits keep the key within 32 bits.
  int bits = 4;
  while (bits < 12 && (std::uint64_t{1} << (2 * bits)) < 16 * std::uint64_t{n}) bits += 4;
  // Halves keep the span finite for coordinates near the double range.
  const double half_span = std::max(0.5 * x1 - 0.5 * x0, 0.5 * y1 - 0.5 * y0);
  const double scale = half_span > 0 ? ((1u << bits) - 1) / half_span : 0.0;
  auto cell = [&](double v, double v0) {
    const double q = (0.5 * v - 0.5 * v0) * scale;  // in [0, 2^bits - 1], never NaN
    return std::min(static_cast<std::uint32_t>(std::max(q, 0.0)), (1u << bits) - 1);
  };
  // BRIO: a point joins round `level` with probability 2^-(level+1) (a coin
  // flipped until heads); rounds go from the highest level, a few dozen
  // points, to level 0, half of them. One stable radix sort on
  // (rounds - level, Hilbert index) orders everything in streaming passes.
  int rounds = 0;
  while (rounds < 15 && (n >> (rounds + 1)) > 32) ++rounds;
  const int key_bits = 2 * bits + 4;
  Rng rng(seed);
  std::vector<std::uint64_t> keys(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec2 p = xy[i];
    const std::uint32_t qx = cell(p.x, x0), qy = cell(p.y, y0);
    const int level = std::min(std::countr_zero(rng.next() | 0x80000000u), rounds);
    const std::uint64_t key = std::uint64_t(rounds - level) << (2 * bits) | hilbert_index(qx, qy, bits);
    keys[i] = key << 32 | i;
  }
  radix_sort_keys(keys, key_bits);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(keys[i]);
  return order;
}

DelaunayResult delaunay(TriangleStore& m, const DelaunayOptions& opt) {
  DelaunayResult res;
  m.corner.clear();
  m.twin.clear();
  m.side_flags.clear();
  m.tri_flags.clear();
  m.free_tris.clear();
  m.out_side.assign(m.num_vertices(), Side{});
  for (const Vec2& p : m.xy)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      res.error = "point coordinates must be finite";
      return res;
    }
  Builder b(m, opt, res);
  b.run();
  return res;
}

}  // namespace sm
