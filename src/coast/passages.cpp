// Passage closing and dams (passages.h): loops are flattened into cyclic node lists, cut
// by 2-opt moves at facing segments, and the changed loops rebuilt into curves.
#include "coast/passages.h"

#include <algorithm>
#include <cstdlib>
#include <array>
#include <bit>
#include <span>
#include <map>
#include <set>
#include <optional>
#include <tuple>
#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "base/check.h"
#include "base/parallel.h"
#include "base/release_memory.h"
#include "coast/coarsen.h"
#include "coast/coastline_option_id.h"
#include "coast/intersections.h"
#include "coast/kept_rope.h"
#include "coast/mean_width.h"
#include "coast/place_pairs.h"
#include "coast/round_segments.h"
#include "coast/segment_grid.h"
#include "exact/ring.h"
#include "exact/predicates.h"
#include "exact/segments.h"
#include "geo/curve_bspline.h"

namespace sm::coast {
namespace {

constexpr double kWidthTolerance = 1e-9;   // relative: "exactly W" stays open
constexpr double kHalfPi = 1.5707963267948966;
// A dam's end makes a corner with the coast it joins; one sharper than this (on the
// water that stays) is a wedge the mesh cannot fill above its quality floor (rho 0.3 needs
// 9.4 degrees at least, mesh/quality_floor.h; at 15 degrees the isoceles triangle has rho
// 0.45). Such a cut is moved to the nearest clean cut without one, its segments at most
// kDamShiftReach kept segments from those found.
constexpr double kMinDamCorner = 15 * kHalfPi / 90;
constexpr int kDamShiftReach = 2;
// The most original points put back on one segment of a refused cut (passages.h).
constexpr std::size_t kMaxPutBack = 4096;

const geo::PolarSphere& unit_sphere() {
  static const geo::PolarSphere ps({0, 0, 0}, 1.0);
  return ps;
}

Vec2 closest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double l2 = norm2(d);
  if (!(l2 > 0)) return a;
  const double t = std::clamp(dot(p - a, d) / l2, 0.0, 1.0);
  return a + t * d;
}

// One point of a flattened loop: the `index`-th point of curve `curve`, or of the points
// added here (dam ends) when curve is kAdded. The node names its point rather than copying
// it: the curves hold the points until the loops are rebuilt, and a copy (48 bytes a node)
// doubled the import's memory on the full-resolution world (9.7 M points). `src` names the
// curve the segment leaving it belongs to (an index into `curves`, or curves.size() + k
// for the k-th dam made here). `kept` shares a word with `index` (12 bytes a node, not 16:
// 39 MB of the pool on the full-resolution world).
constexpr std::uint32_t kAdded = 0xFFFFFFFFu;
constexpr std::uint32_t kMaxIndex = 0x7FFFFFFFu;   // index has 31 bits
struct Node {
  std::uint32_t curve;
  std::uint32_t src;
  std::uint32_t index : 31;
  std::uint32_t kept : 1;
};
static_assert(sizeof(Node) == 12);

// The nodes of every loop and where their points are.
struct PointPool {
  const std::vector<WorkCurve>* curves = nullptr;
  std::vector<Node> nodes = {};
  std::vector<geo::LonLat> added_ll = {};
  std::vector<Vec2> added_uv = {};
  std::vector<double> added_gamma = {};
  Vec2 uv(std::uint32_t i) const {
    const Node& n = nodes[i];
    return n.curve == kAdded ? added_uv[n.index] : (*curves)[n.curve].uv[n.index];
  }
  geo::LonLat ll(std::uint32_t i) const {
    const Node& n = nodes[i];
    return n.curve == kAdded ? added_ll[n.index] : (*curves)[n.curve].full[n.index];
  }
  double gamma(std::uint32_t i) const {
    const Node& n = nodes[i];
    return n.curve == kAdded ? added_gamma[n.index] : (*curves)[n.curve].gamma[n.index];
  }
};

// The points of every loop live once in Work's pool, linked into rings; a loop is its
// first node and its kept nodes (the polygon), a rope of Work::ropes (kept_rope.h). A cut
// relinks four nodes and splits or joins the ropes; neither the original points nor the
// kept ones are copied (a continent's ring is 3 M points at full resolution and 16,000 kept
// at 3 km, and a cut per inlet that copied it made passage closing cuts x ring size).
//
//   pool:  ... a0 -> (originals of a0-a1, dropped) -> a1 ...  b0 -> ... -> b1 ...
//   cut:   next[a0] = b1, next[b0] = a1; src[a0], src[b0] become the two dams
//
// A rope point's metres are those of its kept segment (to the next kept point), measured
// when the segment is made; the value is that of chord() of its two ends whenever it is
// measured, so measuring it early changes no sum.
using Rope = KeptRopes::Rope;
using TreeNode = KeptRopes::TreeNode;
constexpr Rope kNoRope = KeptRopes::kNone;
struct FlatLoop {
  const PointPool* pool = nullptr;
  KeptRopes* ropes = nullptr;
  std::uint32_t head = 0;   // the node the loop's rebuild starts from
  Rope rope = kNoRope;      // kept node ids in ring order from head: the polygon
  // Where a cut that killed this loop (in this round) put its kept positions: position p
  // is at child.offset + (p - from) mod size in loop child.loop when (p - from) mod size <
  // len (close_round follows a candidate's segments through the cuts with it; a per-node
  // index rewritten for every kept point of each new loop was a pass over the continent
  // per cut, and 8 bytes per point of the pool).
  struct Child {
    std::uint32_t loop, from, len, size, offset;
  };
  std::vector<Child> children;
  bool hole = true;
  bool dead = false;
  bool changed = false;
  // Its polygon changed since the last closing round took it (made, or points put back or
  // inserted): that round's polygon and widths (Work::polys) no longer hold.
  bool fresh = true;
  // The polygon's orientation where make_loop found it (fate_of asks again otherwise).
  std::optional<Sign> orientation;
  std::size_t size() const { return ropes->size(rope); }
  TreeNode tree_node(std::size_t j) const { return ropes->at(rope, j % size()); }
  std::uint32_t id(std::size_t j) const { return ropes->id(tree_node(j)); }
  const Node& node(std::size_t j) const { return pool->nodes[id(j)]; }
  Vec2 p(std::size_t j) const { return ropes->uv(tree_node(j)); }
  /// The rope points at positions j .. j + N - 1 (mod size()): one descent and N - 1 steps
  /// (KeptRopes::run), where tree_node() per position descends from the root each time.
  template <std::size_t N>
  std::array<TreeNode, N> run(std::size_t j) const {
    std::array<TreeNode, N> out;
    ropes->run(rope, j, out);
    return out;
  }
  template <std::size_t N>
  std::array<Vec2, N> points(std::size_t j) const {
    const std::array<TreeNode, N> t = run<N>(j);
    std::array<Vec2, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = ropes->uv(t[i]);
    return out;
  }
  geo::LonLat ll(std::size_t j) const { return pool->ll(id(j)); }
  /// Dead: nothing reads it again, so its rope goes back to be reused.
  void kill() {
    dead = true;
    ropes->release(rope);
    rope = kNoRope;
  }
};

struct DamInfo {
  std::size_t record;
  std::int64_t id;
};

using UvKey = std::pair<std::uint64_t, std::uint64_t>;
UvKey uv_key(Vec2 p) { return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y)}; }

// A KeepOpen point's passage: the kept segments (by their start points, which cuts keep)
// of its two banks near it. A cut or dam with one segment on each bank would close it.
struct Gate {
  geo::LonLat where;
  double width = 0;   // metres between the two banks' nearest points
  std::set<UvKey> bank[2];
  bool closes(Vec2 a0, Vec2 b0) const {
    const UvKey a = uv_key(a0), b = uv_key(b0);
    return (bank[0].count(a) && bank[1].count(b)) || (bank[1].count(a) && bank[0].count(b));
  }
};

struct Work {
  std::vector<WorkCurve>& curves;
  const std::size_t n_curves;   // curves before this pass
  const PassageOptions& opt;
  PassageStats& stats;
  PointPool pool = {&curves};                // every loop's points (FlatLoop::pool)
  KeptRopes ropes = {};                      // every live loop's kept points (FlatLoop::rope)
  std::vector<Node>& nodes = pool.nodes;
  std::vector<std::uint32_t> next = {};      // per node: the next node of its ring
  std::vector<FlatLoop> flat = {};
  std::vector<DamInfo> dams = {};
  std::vector<Gate> gates = {};
  // What a closing round keeps for the next (close_round). A round cuts a few places and
  // puts a few points back; measuring every ring's polygon and searching every segment pair
  // again each round made passage closing grow with rounds x coast (the coast bound's points
  // put back add rounds). Per loop (by its number in `flat`, which only grows): the polygon
  // and widths at the round's start, made again only for a loop that is `fresh` (`remade`:
  // per loop, whether it was at this round's start). The round's segments (`segments`,
  // round_segments.h, freed with the rounds): each live loop's kept node ids at the last
  // round's start, so a segment is the same as then when its start node has the same end
  // (a node's point never moves; a node that left the live loops never comes back), and
  // each loop's first segment's number. Only kept nodes start segments (323,000 of 7 M at
  // 3 km on the full GSHHG): two words for every node of the pool were 56 MB under the
  // import's peak, and a hash map from node to segment a cache miss per segment and per
  // near pair each round. `near`: the last round's near pairs (before the one-loop test),
  // by their segments' numbers in that round (sorted), each with its way across once
  // measured (way_across reads only the two segments' points: a pair of unchanged segments
  // keeps it; at a deviation bound's closures most near pairs outlive many rounds).
  struct NearPair {
    std::uint32_t a, b;
    bool measured;
    double across;
    auto key() const { return std::pair(a, b); }
  };
  std::vector<std::vector<Vec2>> polys = {};
  std::vector<std::vector<double>> width = {};
  RoundSegments segments = {};
  std::vector<char> remade = {};
  std::vector<NearPair> near = {};
  bool gate_closed(Vec2 a0, Vec2 b0) const {
    for (const Gate& g : gates)
      if (g.closes(a0, b0)) return true;
    return false;
  }
  std::uint32_t add_node(const Node& n) {
    SM_ASSERT(nodes.size() < kAdded, "close_passages: more points than 32-bit node ids (passages.cpp, add_node)");
    nodes.push_back(n);
    next.push_back(0);
    return static_cast<std::uint32_t>(nodes.size() - 1);
  }
  /// Calls f(node) for every node from `from` (excluded) up to `to` (excluded) along the
  /// ring; a ring has at most every node of the pool, so more steps is a broken ring.
  template <class F>
  void walk(std::uint32_t from, std::uint32_t to, F&& f) {
    std::size_t steps = 0;
    for (std::uint32_t i = next[from]; i != to; i = next[i]) {
      SM_ASSERT(++steps <= nodes.size(), "close_passages: a ring walk did not come back (passages.cpp, Work::walk)");
      f(i);
    }
    stats.node_visits += steps;
  }
};

// Every loop into the pool: its nodes numbered loop after loop, curve after curve (dead
// loops have none), each ring linked, and its kept nodes with their metres made a rope.
// The loops are flattened on the threads in fixed chunks of loops, each writing only its
// own loops' node range (known beforehand from the curves' sizes) and kept lists; the
// ropes are then made on the calling thread in loop order. Node ids and ropes are those of
// one thread whatever the count: the rounds sort segments by node and walk ropes by id.
void flatten_loops(Work& w, const std::vector<WorkLoop>& loops) {
  const std::size_t n = loops.size();
  auto points_of = [&](const WorkCurve& c) { return c.periodic ? c.full.size() : c.full.size() - 1; };
  std::vector<std::size_t> first(n + 1, w.nodes.size());   // loop l's nodes: [first[l], first[l + 1])
  std::size_t room = w.nodes.size();   // every curve's points: an open curve's last is the next one's first
  for (std::size_t l = 0; l < n; ++l) {
    std::size_t m = 0;
    if (!loops[l].dead)
      for (std::uint32_t ci : loops[l].curves) {
        SM_ASSERT(points_of(w.curves[ci]) <= kMaxIndex,
                  "close_passages: a curve with more points than 31-bit indices (passages.cpp, flatten_loops)");
        m += points_of(w.curves[ci]);
        room += w.curves[ci].full.size();
      }
    first[l + 1] = first[l] + m;
  }
  SM_ASSERT(first[n] < kAdded, "close_passages: more points than 32-bit node ids (passages.cpp, flatten_loops)");
  // Sized once, the open curves' spare points as room for the dams' nodes: grown by
  // doubling, the pool would hold up to twice the world's points.
  w.nodes.reserve(room);
  w.next.reserve(room);
  w.nodes.resize(first[n]);
  w.next.resize(first[n]);
  std::vector<std::vector<KeptRopes::Item>> kept_items(n);
  constexpr std::size_t kChunk = 16;   // loops
  parallel_for_chunks(resolve_thread_count(w.opt.threads), n, kChunk, [&](std::size_t b, std::size_t e) {
    std::vector<char> kept;
    for (std::size_t l = b; l < e; ++l) {
      if (loops[l].dead) continue;
      std::vector<KeptRopes::Item>& items = kept_items[l];
      auto id = static_cast<std::uint32_t>(first[l]);
      for (std::uint32_t ci : loops[l].curves) {
        const WorkCurve& c = w.curves[ci];
        kept.assign(c.full.size(), 0);
        for (auto k : c.keep) kept[k] = 1;
        const std::size_t m = points_of(c);
        for (std::size_t i = 0; i < m; ++i, ++id) {
          w.nodes[id] = {ci, ci, static_cast<std::uint32_t>(i) & kMaxIndex, kept[i] != 0};
          if (kept[i]) items.push_back({id, c.uv[i], 0.0});
        }
      }
      for (std::size_t j = 0; j < items.size(); ++j)
        items[j].metres = chord(w.pool.ll(items[j].id), w.pool.ll(items[(j + 1) % items.size()].id), w.opt.radius);
      const auto head = static_cast<std::uint32_t>(first[l]), end = static_cast<std::uint32_t>(first[l + 1]);
      for (std::uint32_t i = head; i < end; ++i) w.next[i] = i + 1 == end ? head : i + 1;
    }
  });
  w.flat.reserve(w.flat.size() + n);
  for (std::size_t l = 0; l < n; ++l) {
    FlatLoop f;
    f.pool = &w.pool;
    f.ropes = &w.ropes;
    f.hole = loops[l].hole;
    f.dead = loops[l].dead;
    f.head = static_cast<std::uint32_t>(first[l]);
    f.rope = w.ropes.make(kept_items[l]);
    std::vector<KeptRopes::Item>().swap(kept_items[l]);
    w.stats.node_visits += first[l + 1] - first[l];
    w.flat.push_back(std::move(f));
  }
}

// The polygon's points in order (one pass over the rope).
std::vector<Vec2> polygon(const FlatLoop& f) {
  std::vector<Vec2> p;
  p.reserve(f.size());
  f.ropes->for_each(f.rope, [&](TreeNode t) { p.push_back(f.ropes->uv(t)); });
  return p;
}

bool in_box(Vec2 p, Vec2 lo, Vec2 hi) { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }

// Whether the cut at a0->a1, b0->b1 can be made: the other segment on the water side of
// each, the two dams a0->b1 and b0->a1 crossing nothing (nor `extra` dams already made),
// and no vertex inside the quad a0 a1 b0 b1 that would become land. `for_segments(lo, hi,
// f)` calls f on every coast segment that may meet the box [lo, hi] until f says true.
template <class ForSegments>
bool cut_is_clean_near(ForSegments&& for_segments, Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1,
                       const std::vector<std::pair<Vec2, Vec2>>& extra) {
  if (orient2d(a0, a1, b0) != Sign::Positive || orient2d(a0, a1, b1) != Sign::Positive ||
      orient2d(b0, b1, a0) != Sign::Positive || orient2d(b0, b1, a1) != Sign::Positive)
    return false;
  if (segments_meet(a0, b1, b0, a1)) return false;
  const std::pair<Vec2, Vec2> dams[2] = {{a0, b1}, {b0, a1}};
  const Vec2 lo{std::min({a0.x, a1.x, b0.x, b1.x}), std::min({a0.y, a1.y, b0.y, b1.y})};
  const Vec2 hi{std::max({a0.x, a1.x, b0.x, b1.x}), std::max({a0.y, a1.y, b0.y, b1.y})};
  auto is_corner = [&](Vec2 p) { return p == a0 || p == a1 || p == b0 || p == b1; };
  auto crosses = [&](Vec2 s0, Vec2 s1) {
    if (std::max(s0.x, s1.x) < lo.x || std::min(s0.x, s1.x) > hi.x || std::max(s0.y, s1.y) < lo.y ||
        std::min(s0.y, s1.y) > hi.y)
      return false;
    if ((s0 == a0 && s1 == a1) || (s0 == b0 && s1 == b1)) return false;   // the two cut segments
    for (const auto& d : dams) {
      if (s0 == d.first || s0 == d.second || s1 == d.first || s1 == d.second) continue;   // its neighbours
      if (segments_meet(d.first, d.second, s0, s1)) return true;
    }
    return false;
  };
  for (const auto& e : extra)
    if (crosses(e.first, e.second)) return false;
  return !for_segments(lo, hi, [&](Vec2 s0, Vec2 s1) {
    if (crosses(s0, s1)) return true;
    return !is_corner(s0) && in_box(s0, lo, hi) && orient2d(a0, a1, s0) == Sign::Positive &&
           orient2d(a1, b0, s0) == Sign::Positive && orient2d(b0, b1, s0) == Sign::Positive &&
           orient2d(b1, a0, s0) == Sign::Positive;
  });
}

// cut_is_clean_near over every segment of the live loops.
bool cut_is_clean(const std::vector<FlatLoop>& flat, Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1,
                  const std::vector<std::pair<Vec2, Vec2>>& extra) {
  auto all = [&](Vec2, Vec2, auto&& f) {
    for (const FlatLoop& l : flat) {
      if (l.dead) continue;
      const std::vector<Vec2> pts = polygon(l);
      for (std::size_t j = 0; j < pts.size(); ++j)
        if (f(pts[j], pts[(j + 1) % pts.size()])) return true;
    }
    return false;
  };
  return cut_is_clean_near(all, a0, a1, b0, b1, extra);
}

std::uint32_t new_dam(Work& w, const Node& from) {
  const std::size_t record = from.src < w.n_curves ? w.curves[from.src].record : w.dams[from.src - w.n_curves].record;
  const std::int64_t id = from.src < w.n_curves ? w.curves[from.src].id : w.dams[from.src - w.n_curves].id;
  w.dams.push_back({record, id});
  return static_cast<std::uint32_t>(w.n_curves + w.dams.size() - 1);
}

// ring_orientation (exact/ring.h) of a rope: the same point (the first of least (y, x)),
// the same neighbours and the same orient2d, found down the tree.
Sign rope_orientation(const KeptRopes& ropes, Rope r) {
  const std::size_t n = ropes.size(r);
  if (n < 3) return Sign::Zero;
  const std::size_t lo = ropes.rank(ropes.lowest(r));
  const Vec2 p_lo = ropes.uv(ropes.at(r, lo));
  std::size_t prev = (lo + n - 1) % n, next = (lo + 1) % n;
  while (prev != lo && ropes.uv(ropes.at(r, prev)) == p_lo) prev = (prev + n - 1) % n;
  while (next != lo && ropes.uv(ropes.at(r, next)) == p_lo) next = (next + 1) % n;
  if (prev == lo || next == lo || prev == next) return Sign::Zero;
  return orient2d(ropes.uv(ropes.at(r, prev)), p_lo, ropes.uv(ropes.at(r, next)));
}

FlatLoop make_loop(Work& w, std::uint32_t head, Rope rope) {
  FlatLoop f;
  f.pool = &w.pool;
  f.ropes = &w.ropes;
  f.head = head;
  f.rope = rope;
  f.changed = true;
  if (f.size() >= 3) f.orientation = rope_orientation(w.ropes, rope);
  f.hole = f.orientation == Sign::Negative;
  return f;
}

struct CutResult {
  std::vector<std::uint32_t> new_loops;
};

// The two ropes a 2-opt at kept segments ja and jb of one loop makes: a1 ... b0 and
// b1 ... a0 (kept positions ja + 1 .. jb and jb + 1 .. ja, cyclic). `r` is used up.
std::pair<Rope, Rope> split_ring(KeptRopes& ropes, Rope r, std::size_t ja, std::size_t jb) {
  const std::size_t k = ropes.size(r);
  const std::size_t from = (ja + 1) % k, len = (jb + k - from) % k + 1;
  return ropes.split(ropes.rotate(r, from), len);
}

// The rope split_ring split, as it was (the same points from the same first one).
Rope unsplit_ring(KeptRopes& ropes, std::pair<Rope, Rope> parts, std::size_t ja) {
  const Rope r = ropes.join(parts.first, parts.second);
  const std::size_t k = ropes.size(r);
  return ropes.rotate(r, (k - (ja + 1) % k) % k);
}

// The metres of the segment (a dam, or one a point left) from kept node a to kept node b,
// on a's rope point t.
void measure_segment(Work& w, TreeNode t, std::uint32_t a, std::uint32_t b) {
  w.ropes.set_metres(t, chord(w.pool.ll(a), w.pool.ll(b), w.opt.radius));
}

// The 2-opt at kept segment ja of loop la and jb of loop lb (see passages.h): four nodes
// relinked, the ropes split or joined; the dropped original points stay unlinked in the
// pool.
CutResult cut(Work& w, std::uint32_t la, std::size_t ja, std::uint32_t lb, std::size_t jb) {
  CutResult r;
  ++w.stats.cuts;
  const FlatLoop& fa = w.flat[la];
  const FlatLoop& fb = w.flat[lb];
  const TreeNode ta0 = fa.tree_node(ja), tb0 = fb.tree_node(jb);
  const std::uint32_t a0 = fa.id(ja), a1 = fa.id(ja + 1);
  const std::uint32_t b0 = fb.id(jb), b1 = fb.id(jb + 1);
  std::vector<Rope> parts;
  std::vector<std::uint32_t> heads;
  const auto next_loop = static_cast<std::uint32_t>(w.flat.size());
  const auto ka = static_cast<std::uint32_t>(fa.size()), kb = static_cast<std::uint32_t>(fb.size());
  const auto sa = static_cast<std::uint32_t>((ja + 1) % ka), sb = static_cast<std::uint32_t>((jb + 1) % kb);
  if (la != lb) {
    // a1 ... a0 then b1 ... b0: one loop.
    parts.push_back(w.ropes.join(w.ropes.rotate(fa.rope, sa), w.ropes.rotate(fb.rope, sb)));
    w.nodes[a0].src = new_dam(w, w.nodes[a0]);   // a0 -> b1
    w.nodes[b0].src = new_dam(w, w.nodes[b0]);   // b0 -> a1
    heads.push_back(a1);
    w.flat[la].rope = w.flat[lb].rope = kNoRope;
    w.flat[la].kill();
    w.flat[lb].kill();
    w.flat[la].children = {{next_loop, sa, ka, ka, 0}};
    w.flat[lb].children = {{next_loop, sb, kb, kb, ka}};
  } else {
    const auto [first, second] = split_ring(w.ropes, fa.rope, ja, jb);
    const auto len1 = static_cast<std::uint32_t>((jb + ka - sa) % ka + 1);
    w.nodes[b0].src = new_dam(w, w.nodes[b0]);   // b0 -> a1
    w.nodes[a0].src = new_dam(w, w.nodes[a0]);   // a0 -> b1
    parts = {first, second};
    heads = {a1, b1};
    w.flat[la].rope = kNoRope;
    w.flat[la].kill();
    w.flat[la].children = {{next_loop, sa, len1, ka, 0}, {next_loop + 1, sb, ka - len1, ka, 0}};
  }
  measure_segment(w, ta0, a0, b1);
  measure_segment(w, tb0, b0, a1);
  w.next[a0] = b1;
  w.next[b0] = a1;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    w.flat.push_back(make_loop(w, heads[i], parts[i]));
    r.new_loops.push_back(static_cast<std::uint32_t>(w.flat.size() - 1));
  }
  return r;
}

// The width below which a passage at `ll` is closed: PassageOptions::width_at when set
// (a time step turned into widths by the depth there), bounded by min_width.
double passage_width_at(const PassageOptions& o, geo::LonLat ll) {
  return o.width_at ? std::min(o.min_width, o.width_at(ll)) : o.min_width;
}

struct Candidate {
  double width;
  std::uint32_t la, sa, lb, sb;   // the loops and kept positions of the two segments at the round's start
  Vec2 where;
};

// Two parts of one ring (kept segments sa and sb of f): a passage only when the way round
// between them is much longer than the way across `d` (not the two sides of a corner). The
// ways round are sums of the kept segments' metres, as a running sum from position 0 once
// gave them: the rope's sums (added in another order) decide when they are farther from
// the bound than the two orders' rounding can differ (each way within about 6 k rounding
// units of the perimeter, k segments; 32 k taken), and the running sum is made again when
// not (near ties only), so that every decision is the running sum's.
bool passage_on_one_ring(const Work& w, const FlatLoop& f, std::size_t sa, std::size_t sb, double d) {
  const std::size_t k = f.size();
  const std::size_t i = std::min(sa, sb), j = std::max(sa, sb);
  const double bound = kHalfPi * d;
  const KeptRopes& ropes = w.ropes;
  const double total = ropes.total_metres(f.rope);
  const double inner = ropes.prefix_metres(f.rope, j) - ropes.prefix_metres(f.rope, i + 1);
  const double outer = total - (ropes.prefix_metres(f.rope, j + 1) - ropes.prefix_metres(f.rope, i));
  const double slack = 16.0 * static_cast<double>(k + 2) * std::numeric_limits<double>::epsilon() * total;
  const double way = std::min(inner, outer);
  if (way - slack > bound) return true;
  if (way + slack < bound) return false;
  std::vector<double> c;
  c.reserve(k + 1);
  c.push_back(0);
  ropes.for_each(f.rope, [&](TreeNode t) { c.push_back(c.back() + ropes.metres(t)); });
  return std::min(c[j] - c[i + 1], c.back() - (c[j + 1] - c[i])) > bound;
}

// What becomes of a new loop: kept, or dropped as degenerate (fewer than 3 points or no
// area) or as water (counter-clockwise) all narrower than the width.
enum class Fate { Kept, Degenerate, Narrow };
// A water loop's mean width (coast/mean_width.h) is read round the ring only when the
// rope's sums leave the answer in doubt, or to be logged (`mean_width`: a Narrow loop's).
Fate fate_of(Work& w, const FlatLoop& f, double* mean_width = nullptr) {
  if (f.size() < 3) return Fate::Degenerate;
  if ((f.orientation ? *f.orientation : rope_orientation(w.ropes, f.rope)) == Sign::Zero) return Fate::Degenerate;
  if (f.hole) return Fate::Kept;
  const double W = passage_width_at(w.opt, f.ll(0));
  if (!(W > 0)) return Fate::Kept;
  ++w.stats.width_tests;
  const std::optional<bool> below = mean_width_surely_below(w.ropes, f.rope, w.opt.radius, W);
  if (below && !(*below && mean_width)) return *below ? Fate::Narrow : Fate::Kept;
  ++w.stats.width_passes;
  const double mw = ring_mean_width_m(w.ropes, f.rope, w.opt.radius);
  if (mean_width) *mean_width = mw;
  return mw < W ? Fate::Narrow : Fate::Kept;
}

// Drops a new loop that fate_of drops; logs narrow water.
void drop_if_narrow(Work& w, std::uint32_t l, std::vector<RepairEntry>& log) {
  FlatLoop& f = w.flat[l];
  double mw = 0;
  const Fate fate = fate_of(w, f, &mw);
  if (fate == Fate::Narrow) {
    const Node& n0 = f.node(0);
    const DamInfo info = n0.src < w.n_curves ? DamInfo{w.curves[n0.src].record, w.curves[n0.src].id}
                                             : w.dams[n0.src - w.n_curves];
    log.push_back({RepairKind::NarrowWater, info.record, info.id, f.ll(0), mw});
  }
  if (fate != Fate::Kept) f.kill();
}

// The fate of each loop the 2-opt at kept segments ja and jb of loop l would make (a1 ...
// b0 first, b1 ... a0 second; `which`: 1 the first only, 2 the second only, 3 both; Kept
// for one not asked): the rope is split, the two looked at and joined back, its points
// and their order as they were.
std::array<Fate, 2> split_fates(Work& w, std::uint32_t l, std::size_t ja, std::size_t jb, int which) {
  const std::pair<Rope, Rope> parts = split_ring(w.ropes, w.flat[l].rope, ja, jb);
  w.flat[l].rope = kNoRope;
  std::array<Fate, 2> fate{Fate::Kept, Fate::Kept};
  const Rope part[2] = {parts.first, parts.second};
  for (int i = 0; i < 2; ++i) {
    if (!(which & (1 << i))) continue;
    FlatLoop trial = make_loop(w, w.ropes.id(w.ropes.at(part[i], 0)), part[i]);
    fate[static_cast<std::size_t>(i)] = fate_of(w, trial);
  }
  w.flat[l].rope = unsplit_ring(w.ropes, parts, ja);
  return fate;
}

// Whether the 2-opt at kept segments ja and jb of loop l leaves a piece that
// drop_if_narrow removes: a dead end filled rather than a passage cut in two.
bool cut_fills_dead_end(Work& w, std::uint32_t l, std::size_t ja, std::size_t jb) {
  const std::array<Fate, 2> fate = split_fates(w, l, ja, jb, 3);
  return fate[0] != Fate::Kept || fate[1] != Fate::Kept;
}

DamInfo info_of(const Work& w, const Node& n) {
  return n.src < w.n_curves ? DamInfo{w.curves[n.src].record, w.curves[n.src].id} : w.dams[n.src - w.n_curves];
}

// The angle of the water at v (water on the left) between the way in from u and the way
// out to x, in [0, 2 pi): the (u,v) map is conformal, so it is the angle on the sphere.
double water_angle(Vec2 u, Vec2 v, Vec2 x) {
  const Vec2 out = x - v, in = u - v;
  const double a = std::atan2(out.x * in.y - out.y * in.x, dot(out, in));
  return a < 0 ? a + 4 * kHalfPi : a;
}

// The sharpest corner, in [0, 2 pi), that a dam from `end` to `across` makes with the coast
// curve leaving `end` through the control points c1, c2, c3 (c1 next to the end), water
// on the left of the way in (`in_side`: the coast comes in to `end`, the dam goes out) or
// of the way out. The coast piece's B-spline (geo/curve_bspline.h: the uniform cubic,
// its end point tripled) leaves the end along c1 - end only for the first sixth of that
// segment: a spike at c1 is cut off, and the curve a mesh-size from the end (where the
// mesh's first edge on it ends) lies towards c2. The corner the mesh gets is the one
// between the dam and the chords from the end to those points: the first three spans
// (they depend on end, c1, c2, c3 alone) are sampled and the sharpest chord kept. The
// control polygon's own corner at the end was 65 degrees where the chord's was 0.5
// (tests/unit/coast/passages_test.cpp, the river mouth of the Gulf of Tonkin).
double dam_corner(Vec2 end, Vec2 across, Vec2 c1, Vec2 c2, Vec2 c3, bool in_side) {
  constexpr int kSpans = 3, kPerSpan = 8;
  const std::array<Vec2, 4> ctrl{end, c1, c2, c3};
  double sharpest = in_side ? water_angle(c1, end, across) : water_angle(across, end, c1);
  for (int i = 1; i <= kSpans * kPerSpan; ++i) {
    // Parameter t of the 4-point open curve (5 pieces): spans 0..2 are t in [0, 3/5].
    const double t = static_cast<double>(i) / (kPerSpan * 5);
    const Vec2 q = geo::eval_bspline_uniform(std::span<const Vec2>(ctrl), false, t).p;
    if (q == end) continue;
    sharpest = std::min(sharpest, in_side ? water_angle(q, end, across) : water_angle(across, end, q));
  }
  return sharpest;
}

// Which end of the dams of the 2-opt at kept segments sa of loop la and sb of lb makes a
// corner sharper than kMinDamCorner with the coast it joins, on water that stays (a piece
// that drop_if_narrow removes does not count): 0 a0, 1 b1, 2 b0, 3 a1; -1 none. The dams
// are a0 -> b1 (corners at a0 and b1) and b0 -> a1 (at b0 and a1); the corner is the one
// between the dam and the coast's curve as drawn near the end (dam_corner).
int sharp_dam_end(Work& w, std::uint32_t la, std::size_t sa, std::uint32_t lb, std::size_t sb) {
  const FlatLoop& fa = w.flat[la];
  const FlatLoop& fb = w.flat[lb];
  // Positions s - 3 .. s + 4 of each loop: pa[3 + i] is fa.p(sa + i).
  const std::array<Vec2, 8> pa = fa.points<8>(sa + fa.size() - 3), pb = fb.points<8>(sb + fb.size() - 3);
  const Vec2 a0 = pa[3], a1 = pa[4], b0 = pb[3], b1 = pb[4];
  const double angle[4] = {dam_corner(a0, b1, pa[2], pa[1], pa[0], true), dam_corner(b1, a0, pb[5], pb[6], pb[7], false),
                           dam_corner(b0, a1, pb[2], pb[1], pb[0], true), dam_corner(a1, b0, pa[5], pa[6], pa[7], false)};
  int first = -1;
  for (int k = 0; k < 4 && first < 0; ++k)
    if (angle[k] < kMinDamCorner) first = k;
  if (first < 0 || la != lb) return first;   // two loops become one, which stays
  // One loop becomes two: b1 ... a0 (corners 0, 1) and a1 ... b0 (corners 2, 3), the
  // second and the first of split_fates. Only a part with a sharp corner is looked at.
  int which = 0;
  for (int k = 0; k < 4; ++k)
    if (angle[k] < kMinDamCorner) which |= k / 2 == 0 ? 2 : 1;
  const std::array<Fate, 2> fate = split_fates(w, la, sa, sb, which);
  for (int k = 0; k < 4; ++k)
    if (angle[k] < kMinDamCorner && fate[k / 2 == 0 ? 1 : 0] == Fate::Kept) return k;
  return -1;
}

// The water's corner at v between the segments u -> v and v -> x, each a dam or a coast
// piece, with the coast's curve as drawn where exactly one is a dam (dam_corner): u2, u3
// the kept points before u, x2, x3 those after x.
double corner_between(bool in_dam, bool out_dam, Vec2 u3, Vec2 u2, Vec2 u, Vec2 v, Vec2 x, Vec2 x2, Vec2 x3) {
  if (out_dam && !in_dam) return dam_corner(v, x, u, u2, u3, true);
  if (in_dam && !out_dam) return dam_corner(v, u, x, x2, x3, false);
  return water_angle(u, v, x);
}

// Whether the kept segment from rope point t (to the next) is a dam (src past the curves).
bool is_dam(const Work& w, TreeNode t) { return w.pool.nodes[w.ropes.id(t)].src >= w.n_curves; }

// A dam end at a corner sharper than kMinDamCorner that no nearby clean cut avoids (the
// pinch of a river mouth behind a spit: the cuts next to it are not clean, the dam runs
// back along the spit's inner side): the wedge of water between the dam and the coast is
// cut off, the dam moved from its end v to the coast's kept point u before it (or from
// the far end to the point after it): u -> x replaces u -> v -> x, the triangle becoming
// land. Only where the triangle is water (its corner at v convex), holds no other point,
// its new side crosses nothing (`near`: the round's segments, `made`: the dams since),
// and the corners at u and x are no sharper than kMinDamCorner; at most kDamShiftReach
// points per dam end. `ends`: the node ids of the cut's dam ends.
template <class Near>
void trim_dam_wedges(Work& w, FlatLoop& f, std::array<TreeNode, 4> ends, Near&& near,
                     std::vector<std::pair<Vec2, Vec2>>& made) {
  for (TreeNode& end : ends)
    for (int step = 0; step < kDamShiftReach; ++step) {
      const std::size_t k = f.size();
      if (k < 8) return;   // the corners read three points each way
      // A dam end's rope point, if it is in f (a point of a piece dropped went back to the
      // free list, and no point has been made since the cut: it is in no live rope).
      if (w.ropes.root_of(end) != f.rope) break;
      const std::size_t j = w.ropes.rank(end);
      // Positions j - 4 .. j + 4: s[4 + i] is f.tree_node(j + i), pt[4 + i] is f.p(j + i).
      const std::array<TreeNode, 9> s = f.run<9>(j + k - 4);
      std::array<Vec2, 9> pt;
      for (std::size_t i = 0; i < 9; ++i) pt[i] = w.ropes.uv(s[i]);
      const bool in_dam = is_dam(w, s[3]), out_dam = is_dam(w, s[4]);
      // The water's corner at the dam end v = pt[4], the coast as drawn three points each way.
      if (in_dam == out_dam ||
          !(corner_between(in_dam, out_dam, pt[1], pt[2], pt[3], pt[4], pt[5], pt[6], pt[7]) < kMinDamCorner))
        break;
      const Vec2 u = pt[3], v = pt[4], x = pt[5];
      if (!(water_angle(u, v, x) < 2 * kHalfPi) || orient2d(u, v, x) == Sign::Zero) break;
      const Sign away = orient2d(u, v, x) == Sign::Positive ? Sign::Negative : Sign::Positive;
      const Vec2 lo{std::min({u.x, v.x, x.x}), std::min({u.y, v.y, x.y})};
      const Vec2 hi{std::max({u.x, v.x, x.x}), std::max({u.y, v.y, x.y})};
      auto inside = [&](Vec2 q) {
        if (q == u || q == v || q == x) return false;
        const Sign o[3] = {orient2d(u, v, q), orient2d(v, x, q), orient2d(x, u, q)};
        return std::none_of(o, o + 3, [&](Sign t) { return t == away; });
      };
      auto crosses = [&](Vec2 s0, Vec2 s1) {
        if (s0 == u || s1 == u || s0 == x || s1 == x) return false;   // its neighbours
        return segments_meet(u, x, s0, s1);
      };
      bool blocked = near(lo, hi, [&](Vec2 s0, Vec2 s1) { return inside(s0) || inside(s1) || crosses(s0, s1); });
      for (const auto& e : made) blocked = blocked || crosses(e.first, e.second);
      if (blocked) break;
      // The corners at u and x once v is gone, u -> x a dam.
      const bool in_dam_u = is_dam(w, s[2]), out_dam_x = is_dam(w, s[5]);
      const double at_u = corner_between(in_dam_u, true, pt[0], pt[1], pt[2], u, x, pt[6], pt[7]);
      const double at_x = corner_between(true, out_dam_x, pt[1], pt[2], u, x, pt[6], pt[7], pt[8]);
      if (!(at_u >= kMinDamCorner && at_x >= kMinDamCorner)) break;
      const TreeNode ut = s[3], xt = s[5];
      const std::uint32_t un = w.ropes.id(ut), vn = w.ropes.id(end), xn = w.ropes.id(xt);
      if (out_dam) w.nodes[un].src = w.nodes[vn].src;   // the dam now leaves u
      w.next[un] = xn;
      if (f.head == vn) f.head = xn;
      const auto [before, from_v] = w.ropes.split(f.rope, j);
      const auto [v_alone, after] = w.ropes.split(from_v, 1);
      w.ropes.release(v_alone);
      f.rope = w.ropes.join(before, after);
      measure_segment(w, ut, un, xn);
      f.orientation.reset();
      f.fresh = true;
      made.push_back({u, x});
      end = out_dam ? ut : xt;
    }
}

// Where the kept segments of the loops made during a round are: a cut leaves every other
// segment as it was (in a new loop, at a new position), so a candidate found at the
// round's start is followed into the loops made since through the positions each cut
// recorded on the loop it killed (FlatLoop::children).
// A round-start loop cut again and again in one round (a continent, one inlet per cut)
// makes a chain of loops, each the one before less the water a cut dropped: walking the
// chain for every candidate on it was cuts x candidates (16% of the CPU on the world at
// 3 km). The chain is kept instead as the set of the loop's positions still in it (a
// Fenwick tree) and the position its current loop starts from: a position's place in the
// current loop is its rank from there. Each position leaves once, so the round's chains
// cost O(size log size) per loop followed.
class ChainTracker {
 public:
  explicit ChainTracker(std::uint32_t l, std::size_t size)
      : loop_(l), count_(size), tree_(size + 1, 0), here_(size, 1) {
    for (std::size_t i = 1; i <= size; ++i) {   // every position present: O(n) build
      tree_[i] += 1;
      if (const std::size_t up = i + (i & (~i + 1)); up <= size) tree_[up] += tree_[i];
    }
  }
  /// Follows the chain from the loop reached so far while each cut of it left one loop that
  /// lives on (the other dropped at once). Stops at a live loop or at another kind of cut.
  void advance(const Work& w) {
    for (std::size_t steps = 0; w.flat[loop_].dead; ++steps) {
      SM_ASSERT(steps <= w.flat.size(), "close_passages: a cut chain did not end (passages.cpp, ChainTracker)");
      const auto& ch = w.flat[loop_].children;
      const FlatLoop::Child* on = nullptr;
      std::size_t going_on = 0;
      for (const FlatLoop::Child& c : ch)
        if (!w.flat[c.loop].dead || !w.flat[c.loop].children.empty()) on = &c, ++going_on;
      if (going_on != 1 || on->offset != 0 || on->size != count_) return;
      // Positions from + len .. from + size - 1 of the current loop (cyclic) leave.
      const std::size_t base = base_;
      std::vector<std::uint32_t> gone;
      gone.reserve(count_ - on->len);
      for (std::size_t t = on->len; t < count_; ++t) gone.push_back(select((base + on->from + t) % count_));
      const std::uint32_t new_start = select((base + on->from) % count_);
      for (std::uint32_t x : gone) remove(x);
      start_ = new_start;
      base_ = rank(start_);
      count_ = on->len;
      loop_ = on->loop;
    }
  }
  /// The loop reached and the place there of the round-start position p (none: p left).
  std::optional<std::pair<std::uint32_t, std::uint32_t>> at(std::uint32_t p) const {
    if (!here_[p]) return std::nullopt;
    const std::size_t r = rank(p), b = base_;
    return std::pair{loop_, static_cast<std::uint32_t>((r + count_ - b) % count_)};
  }

 private:
  // Positions present before x.
  std::size_t rank(std::uint32_t x) const {
    std::size_t r = 0;
    for (std::size_t i = x; i > 0; i -= i & (~i + 1)) r += tree_[i];
    return r;
  }
  // The position with `r` present positions before it.
  std::uint32_t select(std::size_t r) const {
    std::size_t at = 0;
    std::size_t bit = std::bit_floor(tree_.size() - 1);
    for (; bit > 0; bit >>= 1)
      if (at + bit < tree_.size() && tree_[at + bit] <= r) at += bit, r -= tree_[at];
    return static_cast<std::uint32_t>(at);
  }
  void remove(std::uint32_t x) {
    here_[x] = 0;
    for (std::size_t i = std::size_t{x} + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] -= 1;
  }
  std::uint32_t loop_;
  std::size_t count_;
  std::uint32_t start_ = 0;
  std::size_t base_ = 0;   // rank(start_), made again when start_ moves or positions leave
  std::vector<std::uint32_t> tree_;
  // Whether each position is still in the chain: at() asks once per candidate, where two
  // tree walks (a rank each) told it, a cache miss per level on a continent's tree.
  std::vector<char> here_;
};

/// The live loop and kept position of the segment s0 -> s1 that was at kept position j of
/// loop l (none when it is gone: in water dropped, or no longer s0 -> s1). `chains`: the
/// round's trackers, by loop: l's (made by the caller) and those of the loops made this
/// round and cut since, each taking its chain of cuts as far as it can.
std::optional<std::pair<std::uint32_t, std::uint32_t>> follow_find(const Work& w, std::uint32_t l, std::uint32_t j,
                                                                   Vec2 s0, Vec2 s1,
                                                                   std::map<std::uint32_t, ChainTracker>& chains) {
  auto follow = [&](ChainTracker& chain) {
    chain.advance(w);
    const auto there = chain.at(j);
    if (there) std::tie(l, j) = *there;
    return there.has_value();
  };
  if (!follow(chains.at(l))) return std::nullopt;
  // Each step goes to a loop made later: at most one step per loop.
  for (std::size_t steps = 0; w.flat[l].dead; ++steps) {
    SM_ASSERT(steps <= w.flat.size(), "close_passages: a cut loop's children did not end (passages.cpp, follow_find)");
    const FlatLoop::Child* to = nullptr;
    for (const FlatLoop::Child& c : w.flat[l].children)
      if ((j + c.size - c.from) % c.size < c.len) to = &c;
    if (!to) return std::nullopt;
    j = to->offset + (j + to->size - to->from) % to->size;
    l = to->loop;
    // A loop split in two, one part then cut again and again (a continent's two coasts, one
    // inlet per cut): that part's chain taken by a tracker of its own, as the round-start
    // loop's, where each candidate on it walked the chain one cut a step (at 3 km on the
    // full GSHHG about a fifth of passage closing's CPU). Its positions are those it was cut with.
    const FlatLoop& f = w.flat[l];
    if (f.dead && !f.children.empty() && j < f.children.front().size) {
      auto it = chains.find(l);
      if (it == chains.end()) it = chains.emplace(l, ChainTracker(l, f.children.front().size)).first;
      if (!follow(it->second)) return std::nullopt;
    }
  }
  const FlatLoop& f = w.flat[l];
  if (j >= f.size()) return std::nullopt;
  // The segment's end is the next rope point (the first after the last): one descent from
  // the rope's root for both ends, where two were a cache miss per level each on a
  // continent's rope (a third of follow_find's time at 3 km on the full GSHHG).
  const TreeNode t0 = f.tree_node(j);
  if (!(w.ropes.uv(t0) == s0)) return std::nullopt;
  const TreeNode t1 = j + 1 < f.size() ? w.ropes.next(t0) : f.tree_node(0);
  if (!(w.ropes.uv(t1) == s1)) return std::nullopt;
  return std::pair{l, j};
}

// Brings f's kept list up to date after original points between its nodes `from` and `to`
// were marked kept: the entries between them replaced, in ring order. Where the stretch
// wraps past the end of the list (round the loop's head), the list is made again from the
// head, as the positions count from it.
// The rope of kept nodes ids (with their metres) in order, measured now.
Rope make_rope(Work& w, const std::vector<std::uint32_t>& ids, std::uint32_t then) {
  std::vector<KeptRopes::Item> items;
  items.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::uint32_t to = i + 1 < ids.size() ? ids[i + 1] : then;
    items.push_back({ids[i], w.pool.uv(ids[i]), chord(w.pool.ll(ids[i]), w.pool.ll(to), w.opt.radius)});
  }
  return w.ropes.make(items);
}

// The kept position of node `id` in f, its rope point `t` when that still holds it (a
// loop made again from its head gave its points new rope points), else found in order.
std::size_t position_of(const Work& w, const FlatLoop& f, TreeNode t, std::uint32_t id) {
  if (w.ropes.root_of(t) == f.rope && w.ropes.id(t) == id) return w.ropes.rank(t);
  std::size_t j = 0, at = f.size();
  w.ropes.for_each(f.rope, [&](TreeNode x) {
    if (w.ropes.id(x) == id && at == f.size()) at = j;
    ++j;
  });
  return at;
}

void rekeep(Work& w, FlatLoop& f, TreeNode from_t, std::uint32_t from, TreeNode to_t, std::uint32_t to) {
  f.orientation.reset();
  f.fresh = true;
  const std::size_t k = f.size();
  const std::size_t i = position_of(w, f, from_t, from), t = position_of(w, f, to_t, to);
  SM_ASSERT(i < k && t < k, "close_passages: a refused cut's segment is not in its loop (passages.cpp, rekeep)");
  std::vector<std::uint32_t> between;
  if (t > i) {
    w.walk(from, to, [&](std::uint32_t n) {
      if (w.nodes[n].kept) between.push_back(n);
    });
    // Positions i + 1 .. t - 1 replaced by `between`; segment i and the new ones measured.
    const auto [head, rest] = w.ropes.split(f.rope, i + 1);
    const auto [old_mid, tail] = w.ropes.split(rest, t - (i + 1));
    w.ropes.release(old_mid);
    const TreeNode i_t = w.ropes.at(head, i);
    f.rope = w.ropes.join(w.ropes.join(head, make_rope(w, between, to)), tail);
    measure_segment(w, i_t, from, between.empty() ? to : between.front());
    return;
  }
  if (w.nodes[f.head].kept) between.push_back(f.head);
  w.walk(f.head, f.head, [&](std::uint32_t n) {
    if (w.nodes[n].kept) between.push_back(n);
  });
  w.ropes.release(f.rope);
  f.rope = make_rope(w, between, between.empty() ? 0 : between.front());
}

// One round of automatic closures: the narrowest clean cut of each loop. False: none left.
// The near misses of the round-start polygons w.polys, as find_near_misses gives them: the
// pairs of two segments unchanged since the last round are that round's (the test reads
// only their points and widths), and only the segments new since then are searched.
std::vector<NearMiss> round_near_misses(Work& w) {
  RoundSegments::Round round = w.segments.next(
      w.flat.size(), w.ropes.capacity(), [&](std::uint32_t l) { return !w.flat[l].dead; }, [&](std::uint32_t l) { return w.remade[l] != 0; },
      [&](std::uint32_t l, std::vector<std::uint32_t>& ids, std::vector<std::uint32_t>& keys) {
        w.ropes.for_each(w.flat[l].rope, [&](TreeNode t) {
          ids.push_back(w.ropes.id(t));
          keys.push_back(t);   // a cut moves rope points to the new loops: most keep their segment
        });
      });
  std::vector<std::vector<char>>& active = round.active;
  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& at = round.at;
  const std::vector<std::uint32_t>& renumber = round.renumber;
  auto first = [&](std::uint32_t l) { return w.segments.first(l); };
  std::size_t searched = 0;
  std::vector<NearMiss> near =
      find_near_pairs(w.polys, w.width, active, &searched, resolve_thread_count(w.opt.threads));
  w.stats.near_searched += searched;
  std::vector<std::vector<char>>().swap(active);
  // The search's grid and per-chunk lists are freed: their pages go back before the round's
  // next arrays (candidates, the clean test's grid) are made, else they stay resident under
  // them (the first round at 3 km: 50 MB freed but resident, the import's peak).
  release_free_memory();
  near.reserve(near.size() + w.near.size());
  std::vector<Work::NearPair> pairs;   // this round's, in the order of `near`
  pairs.reserve(near.capacity());
  for (const NearMiss& m : near)
    pairs.push_back({static_cast<std::uint32_t>(first(m.loop_a) + m.seg_a),
                     static_cast<std::uint32_t>(first(m.loop_b) + m.seg_b), false, 0.0});
  for (const Work::NearPair& p : w.near) {
    const std::uint32_t sa = renumber[p.a], sb = renumber[p.b];
    if (sa == RoundSegments::kNone || sb == RoundSegments::kNone) continue;
    NearMiss m{at[sa].first, at[sa].second, at[sb].first, at[sb].second, 0, {}};
    order_places(m);
    // The way across kept only with the segments in the same roles: with width_at the
    // width is read at the mean of the four points, added in the pair's order.
    const bool same_roles = m.loop_a == at[sa].first && m.seg_a == at[sa].second;
    near.push_back(m);
    pairs.push_back({static_cast<std::uint32_t>(first(m.loop_a) + m.seg_a),
                     static_cast<std::uint32_t>(first(m.loop_b) + m.seg_b),
                     p.measured && (same_roles || !w.opt.width_at), p.across});
    ++w.stats.near_kept;
  }
  std::vector<Work::NearPair>().swap(w.near);   // read: freed before the round's order is made
  // In place-pair order (sort_place_pairs): a loop's segments are numbered on from its
  // first(), in loop order, so (loop_a, seg_a, loop_b, seg_b) orders as the two numbers do.
  // Sorted as one 64-bit key a pair (the four-field comparison over 40-byte records was
  // most of a round's sort); the keys are unique (a new pair has a new segment, a kept one
  // none), so the order is the one sort_place_pairs gives. One sort orders both the pairs
  // kept for the next round and the near misses (those of one loop too near along it left
  // out: within one loop only far-apart parts count, at least 3 segments away both ways as
  // find_near_misses, with the loop as it is now).
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(near.size());
  for (std::size_t i = 0; i < near.size(); ++i)
    order[i] = {(std::uint64_t{pairs[i].a} << 32) | pairs[i].b, static_cast<std::uint32_t>(i)};
  std::sort(order.begin(), order.end());
  auto near_along = [&](const NearMiss& m) {
    if (m.loop_a != m.loop_b) return false;
    const std::uint32_t n = static_cast<std::uint32_t>(w.polys[m.loop_a].size());
    const std::uint32_t d = m.seg_a > m.seg_b ? m.seg_a - m.seg_b : m.seg_b - m.seg_a;
    return std::min(d, n - d) < 3;
  };
  // The pairs put in that order where they are (each cycle of the permutation followed once,
  // its entries' keys, read no more, marking them done): a sorted copy would be made where
  // the old list's pages were freed but stay resident (the first round is the import's peak).
  constexpr std::uint64_t kDone = ~std::uint64_t{0};
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i].first == kDone) continue;
    const Work::NearPair held = pairs[i];
    std::size_t j = i;
    for (std::size_t steps = 0; steps < order.size(); ++steps) {   // a cycle is at most every entry
      const std::size_t from = order[j].second;
      order[j].first = kDone;
      if (from == i) {
        pairs[j] = held;
        break;
      }
      pairs[j] = pairs[from];
      j = from;
    }
  }
  w.near = std::move(pairs);
  std::vector<NearMiss> sorted;
  sorted.reserve(near.size());
  for (const auto& o : order)
    if (!near_along(near[o.second])) sorted.push_back(near[o.second]);
  return sorted;
}

// The round-start polygons and widths (Work::polys, width): those of loops unchanged since
// the last round kept.
void round_polygons(Work& w) {
  const double W = w.opt.min_width, R = w.opt.radius;
  w.polys.resize(w.flat.size());
  w.width.resize(w.flat.size());
  w.remade.assign(w.flat.size(), 0);
  for (std::size_t l = 0; l < w.flat.size(); ++l) {
    FlatLoop& f = w.flat[l];
    w.remade[l] = f.fresh;
    if (f.dead) {
      std::vector<Vec2>().swap(w.polys[l]);
      std::vector<double>().swap(w.width[l]);
      continue;
    }
    if (!f.fresh) {
      ++w.stats.polygons_kept;
      continue;
    }
    w.polys[l] = polygon(f);
    w.width[l].clear();
    for (Vec2 p : w.polys[l]) w.width[l].push_back(1.01 * W / lambda_m(p, R));
    f.fresh = false;
    ++w.stats.polygons_made;
  }
}

// The way across a near miss in metres when it is a candidate: facing segments closer than
// the width there (NaN: not one).
double way_across(const Work& w, const NearMiss& m) {
  const double R = w.opt.radius;
  const auto& pa = w.polys[m.loop_a];
  const auto& pb = w.polys[m.loop_b];
  const Vec2 a0 = pa[m.seg_a], a1 = pa[(m.seg_a + 1) % pa.size()];
  const Vec2 b0 = pb[m.seg_b], b1 = pb[(m.seg_b + 1) % pb.size()];
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  if (dot(a1 - a0, b1 - b0) >= 0) return kNone;   // not facing
  const double d = std::min({uv_point_segment_metres(a0, b0, b1, R), uv_point_segment_metres(a1, b0, b1, R),
                             uv_point_segment_metres(b0, a0, a1, R), uv_point_segment_metres(b1, a0, a1, R)});
  const Vec2 mid = 0.25 * (a0 + a1 + b0 + b1);
  const double W = w.opt.width_at ? passage_width_at(w.opt, unit_sphere().lonlat_from_param(mid)) : w.opt.min_width;
  return d < W * (1 - kWidthTolerance) ? d : kNone;
}

// The round's candidates, narrowest first: near misses of facing segments closer than the
// width there, two parts of one ring only when the way round is much longer. The ways
// across (four points' distances on the sphere each, 150,000 near misses a round at 3 km)
// are measured on threads, in fixed chunks, unless the width comes from width_at (a depth
// look-up not known to be safe to share); the ropes' sums are read in order after.
std::vector<Candidate> round_candidates(Work& w) {
  std::vector<NearMiss> near = round_near_misses(w);
  // KeepPassages: a cut joining two loops is never made, and a round's cuts only split
  // loops, so two round-start loops' segments stay on two loops (close_round would follow
  // the pair and skip it; at 3 km, 128,000 of the 524,000 candidates of six rounds).
  if (w.opt.keep_passages) std::erase_if(near, [](const NearMiss& m) { return m.loop_a != m.loop_b; });
  // Each near pair's entry in w.near, whose way across is kept from the round it was
  // measured in; the others measured now and kept there. Both lists are in key order (the
  // near pairs are a part of w.near, round_near_misses), so the entries are found in one
  // pass (a binary search a pair was a cache miss a level).
  std::vector<std::size_t> entry(near.size());
  std::vector<std::size_t> to_measure;
  std::vector<double> across(near.size());
  auto it = w.near.begin();
  for (std::size_t i = 0; i < near.size(); ++i) {
    const NearMiss& m = near[i];
    const std::pair key(static_cast<std::uint32_t>(w.segments.first(m.loop_a) + m.seg_a),
                        static_cast<std::uint32_t>(w.segments.first(m.loop_b) + m.seg_b));
    while (it != w.near.end() && it->key() < key) ++it;
    SM_ASSERT(it != w.near.end() && it->key() == key,
              "close_passages: a near pair not in the round's list (passages.cpp, round_candidates)");
    entry[i] = static_cast<std::size_t>(it - w.near.begin());
    if (it->measured)
      across[i] = it->across;
    else
      to_measure.push_back(i);
  }
  w.stats.across_kept += near.size() - to_measure.size();
  constexpr std::size_t kChunk = 4096;
  parallel_for_chunks(w.opt.width_at ? 1 : resolve_thread_count(w.opt.threads), to_measure.size(), kChunk,
                      [&](std::size_t b, std::size_t e) {
                        for (std::size_t i = b; i < e; ++i) across[to_measure[i]] = way_across(w, near[to_measure[i]]);
                      });
  for (std::size_t i : to_measure) w.near[entry[i]].measured = true, w.near[entry[i]].across = across[i];
  std::vector<Candidate> cands;
  for (std::size_t i = 0; i < near.size(); ++i) {
    const NearMiss& m = near[i];
    const double d = across[i];
    if (std::isnan(d)) continue;
    if (m.loop_a == m.loop_b && !passage_on_one_ring(w, w.flat[m.loop_a], m.seg_a, m.seg_b, d)) continue;
    const auto& pa = w.polys[m.loop_a];
    const auto& pb = w.polys[m.loop_b];
    const Vec2 mid = 0.25 * (pa[m.seg_a] + pa[(m.seg_a + 1) % pa.size()] + pb[m.seg_b] + pb[(m.seg_b + 1) % pb.size()]);
    cands.push_back({d, m.loop_a, m.seg_a, m.loop_b, m.seg_b, mid});
  }
  std::stable_sort(cands.begin(), cands.end(),
                   [](const Candidate& x, const Candidate& y) { return x.width < y.width; });
  return cands;
}

// A dam end at a corner sharper than the mesh can follow (a coast point the deviation
// bound put back next to the mouth of an inlet, and the dam nearly doubling back along the
// coast): the nearest clean cut without such a corner, segments up to kDamShiftReach from
// kept segments sa of la and sb of lb (nearest first, in a fixed order); none: nullopt.
template <class Near>
std::optional<std::pair<std::size_t, std::size_t>> unsharp_cut(Work& w, std::uint32_t la, std::size_t sa,
                                                              std::uint32_t lb, std::size_t sb, Near&& near,
                                                              const std::vector<std::pair<Vec2, Vec2>>& made) {
  const std::size_t ka = w.flat[la].size(), kb = w.flat[lb].size();
  const auto shifted = [](std::size_t j, int d, std::size_t k) {
    const long kl = static_cast<long>(k);
    return static_cast<std::size_t>(((static_cast<long>(j) + d) % kl + kl) % kl);
  };
  for (int reach = 1; reach <= kDamShiftReach; ++reach)
    for (int da = -reach; da <= reach; ++da)
      for (int db = -reach; db <= reach; ++db) {
        if (std::max(std::abs(da), std::abs(db)) != reach) continue;   // the ring at this reach
        const std::size_t ta = shifted(sa, da, ka), tb = shifted(sb, db, kb);
        // On one loop the two segments must stay apart (a cut of neighbours is no cut).
        if (la == lb && (ta == tb || (ta + 1) % ka == tb || (tb + 1) % ka == ta)) continue;
        const FlatLoop& fa = w.flat[la];
        const FlatLoop& fb = w.flat[lb];
        const std::array<Vec2, 2> pa = fa.points<2>(ta), pb = fb.points<2>(tb);
        if (w.gate_closed(pa[0], pb[0]) || !cut_is_clean_near(near, pa[0], pa[1], pb[0], pb[1], made) ||
            sharp_dam_end(w, la, ta, lb, tb) >= 0)
          continue;
        return std::pair{ta, tb};
      }
  return std::nullopt;
}

// A cut refused for not being clean: one of its segments (its end points' rope points and
// nodes, in its loop then) and the other segment.
struct RefusedCut {
  std::uint32_t loop;
  TreeNode from_t, to_t;
  std::uint32_t from, to;
  Vec2 o0, o1;
};

// The refused cuts' segments: their original points within W of the other segment kept
// (a loop a cut replaced since is skipped), only where those cross nothing: not the round's
// segments (but the one they replace), the dams made, the points put back before, nor
// themselves (the source may cross itself where the coarse segment did not). Whether any
// point was put back.
bool put_back_refused(Work& w, const std::vector<RefusedCut>& refused, SegmentGrid& grid,
                      const std::vector<std::pair<Vec2, Vec2>>& made) {
  const double W = w.opt.min_width, R = w.opt.radius;
  bool any = false;
  std::vector<std::pair<Vec2, Vec2>> put_back;
  for (const auto& [l, from_t, to_t, from, to, o0, o1] : refused) {
    FlatLoop& f = w.flat[l];
    if (f.dead) continue;
    std::vector<std::uint32_t> run;   // the original points within W of the other segment
    const Vec2 other0 = o0, other1 = o1;   // clang 14 lambdas cannot capture structured bindings
    w.walk(from, to, [&](std::uint32_t i) {
      if (!w.nodes[i].kept && uv_point_segment_metres(w.pool.uv(i), other0, other1, R) < W) run.push_back(i);
    });
    if (run.empty() || run.size() > kMaxPutBack) continue;
    std::vector<Vec2> pts{w.pool.uv(from)};
    for (std::uint32_t i : run) pts.push_back(w.pool.uv(i));
    pts.push_back(w.pool.uv(to));
    const Vec2 c0 = pts.front(), c1 = pts.back();
    auto meets = [](Vec2 p, Vec2 q, Vec2 r, Vec2 t) {
      if (p == r || p == t || q == r || q == t) return false;   // neighbours at a shared end
      return segments_meet(p, q, r, t);
    };
    bool crosses = false;
    for (std::size_t i = 0; i + 1 < pts.size() && !crosses; ++i) {
      const Vec2 p = pts[i], q = pts[i + 1];
      const Vec2 lo{std::min(p.x, q.x), std::min(p.y, q.y)}, hi{std::max(p.x, q.x), std::max(p.y, q.y)};
      crosses = grid.any_near(lo, hi, [&](Vec2 r, Vec2 t) { return !(r == c0 && t == c1) && meets(p, q, r, t); });
      for (const auto& e : made) crosses = crosses || meets(p, q, e.first, e.second);
      for (const auto& e : put_back) crosses = crosses || meets(p, q, e.first, e.second);
      for (std::size_t k = i + 2; k + 1 < pts.size() && !crosses; ++k) crosses = meets(p, q, pts[k], pts[k + 1]);
    }
    if (crosses) continue;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) put_back.push_back({pts[i], pts[i + 1]});
    for (std::uint32_t i : run) w.nodes[i].kept = true;
    rekeep(w, f, from_t, from, to_t, to);
    f.changed = true;
    any = true;
  }
  return any;
}

// One round of automatic closures: the narrowest clean cut of each loop. False: none left.
bool close_round(Work& w, std::vector<RepairEntry>& log) {
  round_polygons(w);
  const std::vector<std::vector<Vec2>>& polys = w.polys;
  const std::vector<Candidate> cands = round_candidates(w);
  release_free_memory();   // the round's near pairs and ways across (round_near_misses)
  // The round's segments as they were at its start: the cuts made since only replaced two
  // segments by two dams (in `made`) or dropped water, so checking against the start's
  // segments too is the same or stricter (a stricter refusal is retried next round).
  // Made at the round's first test (a round whose candidates all fall before it, the last
  // one among them, makes none: a grid of the world's segments).
  std::optional<SegmentGrid> grid;
  auto the_grid = [&]() -> SegmentGrid& {
    if (!grid) grid.emplace(polys);
    return *grid;
  };
  auto near = [&](Vec2 lo, Vec2 hi, auto&& f) { return the_grid().any_near(lo, hi, f); };
  std::vector<std::pair<Vec2, Vec2>> made;
  std::vector<RefusedCut> refused;
  std::map<std::uint32_t, ChainTracker> chains;   // per loop cut this round (follow_find)
  bool any = false;
  for (const Candidate& c : cands) {
    const auto& pa = polys[c.la];
    const auto& pb = polys[c.lb];
    const Vec2 a0 = pa[c.sa], a1 = pa[(c.sa + 1) % pa.size()];
    const Vec2 b0 = pb[c.sb], b1 = pb[(c.sb + 1) % pb.size()];
    // Its segments where they are now: as found, or in the loops a cut made this round
    // (where the one-ring test is made again, as the next round would).
    const auto where = [&](std::uint32_t l, std::uint32_t j, Vec2 s0, Vec2 s1) {
      if (!w.flat[l].dead) return std::optional<std::pair<std::uint32_t, std::uint32_t>>{{l, j}};
      if (!chains.count(l)) chains.emplace(l, ChainTracker(l, polys[l].size()));
      return follow_find(w, l, j, s0, s1, chains);
    };
    const auto ra = where(c.la, c.sa, a0, a1), rb = where(c.lb, c.sb, b0, b1);
    if (!ra || !rb) continue;
    const auto [la, sa] = *ra;
    const auto [lb, sb] = *rb;
    const bool followed = w.flat[c.la].dead || w.flat[c.lb].dead;
    if (followed && la == lb && (sa == sb || !passage_on_one_ring(w, w.flat[la], sa, sb, c.width))) continue;
    if (w.opt.keep_passages && la != lb) continue;   // a strait between two coasts
    if (w.gate_closed(a0, b0)) continue;              // a passage kept open
    const bool clean = cut_is_clean_near(near, a0, a1, b0, b1, made);
    // A dam end at a corner sharper than the mesh can follow: the cut moves to the nearest
    // clean one without such a corner (unsharp_cut); without one it is made as found and
    // the wedge of water at the sharp end is cut off where it can be (trim_dam_wedges),
    // else the mesh reports the corner.
    std::size_t sa_cut = sa, sb_cut = sb;
    bool sharp = clean && sharp_dam_end(w, la, sa, lb, sb) >= 0;
    if (sharp) {
      const auto moved = unsharp_cut(w, la, sa, lb, sb, near, made);
      if (moved) std::tie(sa_cut, sb_cut) = *moved;
      sharp = !moved;
    }
    if (!clean) {
      // Long segments at a pinch (a 30 m strait between 2 km segments) make no clean
      // quad: their original points within W of the other side are put back at the
      // round's end and the place is tried again, so that a passage narrower than W is
      // not left open for that (KeepPassages = 0: every such passage is to be closed).
      if (!w.opt.keep_passages) {
        const FlatLoop& fa = w.flat[la];
        const FlatLoop& fb = w.flat[lb];
        const std::array<TreeNode, 2> ta = fa.run<2>(sa), tb = fb.run<2>(sb);
        refused.push_back({la, ta[0], ta[1], w.ropes.id(ta[0]), w.ropes.id(ta[1]), b0, b1});
        refused.push_back({lb, tb[0], tb[1], w.ropes.id(tb[0]), w.ropes.id(tb[1]), a0, a1});
      }
      continue;
    }
    if (w.opt.keep_passages && !cut_fills_dead_end(w, la, sa_cut, sb_cut)) continue;   // a passage
    const std::array<TreeNode, 2> ea = w.flat[la].run<2>(sa_cut), eb = w.flat[lb].run<2>(sb_cut);
    made.push_back({w.ropes.uv(ea[0]), w.ropes.uv(eb[1])});
    made.push_back({w.ropes.uv(eb[0]), w.ropes.uv(ea[1])});
    const DamInfo info = info_of(w, w.pool.nodes[w.ropes.id(ea[0])]);
    const std::array<TreeNode, 4> ends{ea[0], ea[1], eb[0], eb[1]};
    const CutResult r = cut(w, la, sa_cut, lb, sb_cut);
    std::size_t dropped = 0;
    for (std::uint32_t l : r.new_loops) {
      drop_if_narrow(w, l, log);
      dropped += w.flat[l].dead;
      if (sharp && !w.flat[l].dead) trim_dam_wedges(w, w.flat[l], ends, near, made);
    }
    if (dropped == 0)   // a cut that only trims narrow water is listed as NarrowWater
      log.push_back(
          {RepairKind::ClosedPassage, info.record, info.id, unit_sphere().lonlat_from_param(c.where), c.width});
    any = true;
  }
  return (!refused.empty() && put_back_refused(w, refused, the_grid(), made)) || any;
}

// Inserts a kept node at uv point x on kept segment j of loop f (its original points
// dropped); returns the new node's id. The loop then starts at the segment's end b and its
// kept list runs b ... a x, as the loop's order decides where its rebuild starts.
std::uint32_t insert_on(Work& w, FlatLoop& f, std::size_t j, Vec2 x) {
  const std::size_t k = f.size();
  const std::uint32_t a = f.id(j), b = f.id(j + 1);
  const TreeNode ta = f.tree_node(j);
  const Vec2 ua = w.pool.uv(a), ub = w.pool.uv(b);
  if (x == ua) return a;   // the dam meets the coast at a vertex: no new point
  if (x == ub) return b;
  const double t = norm(x - ua) / std::max(norm(ub - ua), 1e-300);
  const double ga = w.pool.gamma(a), gb = w.pool.gamma(b);
  w.pool.added_ll.push_back(unit_sphere().lonlat_from_param(x));
  w.pool.added_uv.push_back(x);
  w.pool.added_gamma.push_back(ga + t * (gb - ga));
  SM_ASSERT(w.pool.added_uv.size() <= kMaxIndex,
            "close_passages: more dam points than 31-bit indices (passages.cpp, insert_on)");
  const std::uint32_t at =
      w.add_node({kAdded, w.nodes[a].src, static_cast<std::uint32_t>(w.pool.added_uv.size() - 1) & kMaxIndex, true});
  w.next[a] = at;
  w.next[at] = b;
  const std::vector<std::uint32_t> x_alone{at};
  f.rope = w.ropes.join(w.ropes.rotate(f.rope, (j + 1) % k), make_rope(w, x_alone, b));
  // a (now last but one) -> x and x -> b are new segments.
  measure_segment(w, ta, a, at);
  f.head = b;
  f.changed = true;
  f.fresh = true;
  f.orientation.reset();
  return at;
}

std::size_t kept_position(const FlatLoop& f, std::uint32_t node) {
  std::size_t j = 0, at = f.size();
  f.ropes->for_each(f.rope, [&](TreeNode t) {
    if (f.ropes->id(t) == node && at == f.size()) at = j;
    ++j;
  });
  return at;
}

// The kept segment of f crossed by p-q closest to x (x was constructed on it).
std::size_t crossed_segment(const FlatLoop& f, Vec2 p, Vec2 q, Vec2 x) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  const std::vector<Vec2> pts = polygon(f);
  for (std::size_t j = 0; j < pts.size(); ++j) {
    const Vec2 s0 = pts[j], s1 = pts[(j + 1) % pts.size()];
    if (!segments_meet(s0, s1, p, q)) continue;
    const double d = norm(closest_on_segment(x, s0, s1) - x);
    if (d < best_d) best_d = d, best = j;
  }
  return best;
}

struct Crossing {
  double t;
  std::uint32_t loop, seg;
  bool entering;   // into the water (the dam goes from the segment's right to its left)
  Vec2 x;
};

// A dam by hand from p to q: cuts across each stretch of water it crosses.
Result<std::size_t> place_dam(Work& w, geo::LonLat p_ll, geo::LonLat q_ll, std::vector<RepairEntry>& log) {
  const Vec2 p = unit_sphere().param_from_lonlat(p_ll), q = unit_sphere().param_from_lonlat(q_ll);
  std::vector<Crossing> xs;
  for (std::uint32_t l = 0; l < w.flat.size(); ++l) {
    const FlatLoop& f = w.flat[l];
    if (f.dead) continue;
    const std::vector<Vec2> pts = polygon(f);
    for (std::uint32_t j = 0; j < pts.size(); ++j) {
      const Vec2 s0 = pts[j], s1 = pts[(j + 1) % pts.size()];
      const Sign o0 = orient2d(s0, s1, p), o1 = orient2d(s0, s1, q);
      const Sign o2 = orient2d(p, q, s0), o3 = orient2d(p, q, s1);
      if (o0 == Sign::Zero || o1 == Sign::Zero || o0 == o1) continue;   // a dam end on the coast: no crossing
      // A coast vertex on the dam line counts on its right (as if moved off it), so that
      // exactly one of its two segments crosses the line where the coast does.
      if ((o2 == Sign::Positive) == (o3 == Sign::Positive)) continue;
      const double c1 = cross(s1 - s0, p - s0), c2 = cross(s1 - s0, q - s0);
      const double t = c1 / (c1 - c2);
      const Vec2 x = o2 == Sign::Zero ? s0 : o3 == Sign::Zero ? s1 : p + t * (q - p);
      xs.push_back({t, l, j, o0 == Sign::Negative, x});
    }
  }
  std::stable_sort(xs.begin(), xs.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
  std::size_t placed = 0;
  // Water stretches: an entering crossing followed by a leaving one. Each is cut on the
  // polygons as they are now; later stretches are found again on the changed loops.
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    if (!xs[i].entering || xs[i + 1].entering) continue;
    const Crossing in = xs[i], out = xs[i + 1];
    if (!w.flat[in.loop].dead && !w.flat[out.loop].dead &&
        w.gate_closed(w.flat[in.loop].p(in.seg), w.flat[out.loop].p(out.seg)))
      for (const Gate& g : w.gates)
        if (g.closes(w.flat[in.loop].p(in.seg), w.flat[out.loop].p(out.seg)))
          return CoastError{coast_option_string(CoastOpt::KeepOpen), -1,
                            fmt::format("the KeepOpen point (lon {:.6f}, lat {:.6f}) keeps open the passage that the "
                                        "dam from (lon {:.6f}, lat {:.6f}) to (lon {:.6f}, lat {:.6f}) closes: remove "
                                        "one of them",
                                        g.where.lon, g.where.lat, p_ll.lon, p_ll.lat, q_ll.lon, q_ll.lat),
                            g.where};
    if (w.flat[in.loop].dead || w.flat[out.loop].dead) {
      // The loop was cut by this dam's previous stretch: place the rest as a new dam.
      auto rest = place_dam(w, unit_sphere().lonlat_from_param(xs[i].x - 1e-9 * (q - p)), q_ll, log);
      if (!rest) return rest;
      return placed + *rest;
    }
    const double len = norm(out.x - in.x);
    // On the segment entered: a0 -> X2 -> X -> a1; on the one left: b0 -> Y -> Y2 -> b1.
    // The dam Y -> X closes the water, X2 -> Y2 (one dam length away) bounds the removed quad.
    auto toward = [len](Vec2 from, Vec2 to) {
      return from + std::min(1.0, len / std::max(norm(to - from), 1e-300)) * 0.5 * (to - from);
    };
    FlatLoop& fa = w.flat[in.loop];
    const std::uint32_t nx = insert_on(w, fa, in.seg, in.x);
    const std::size_t jx = kept_position(fa, nx), ka = fa.size();
    insert_on(w, fa, (jx + ka - 1) % ka, toward(in.x, fa.p(jx + ka - 1)));
    FlatLoop& fb = w.flat[out.loop];
    const std::uint32_t ny = insert_on(w, fb, crossed_segment(fb, p, q, out.x), out.x);
    const std::size_t jy = kept_position(fb, ny);
    insert_on(w, fb, jy, toward(out.x, fb.p(jy + 1)));
    // Kept positions of X2 and Y (segments X2 -> X and Y -> Y2).
    FlatLoop& fa2 = w.flat[in.loop];
    const std::vector<Vec2> pa = polygon(fa2), pb = polygon(w.flat[out.loop]);
    std::size_t ja = pa.size(), jb = pb.size();
    for (std::size_t j = 0; j < pa.size(); ++j)
      if (pa[(j + 1) % pa.size()] == in.x) ja = j;
    const FlatLoop& fb2 = w.flat[out.loop];
    for (std::size_t j = 0; j < pb.size(); ++j)
      if (pb[j] == out.x) jb = j;
    if (ja == pa.size() || jb == pb.size() ||
        !cut_is_clean(w.flat, fa2.p(ja), fa2.p(ja + 1), fb2.p(jb), fb2.p(jb + 1), {}))
      return CoastError{
          coast_option_string(CoastOpt::Dams), -1,
          fmt::format("the dam from (lon {:.6f}, lat {:.6f}) to (lon {:.6f}, lat {:.6f}) cannot close the "
                      "water it crosses without crossing another coastline: move its ends onto the "
                      "nearest land on each side",
                      p_ll.lon, p_ll.lat, q_ll.lon, q_ll.lat),
          unit_sphere().lonlat_from_param(0.5 * (in.x + out.x))};
    const DamInfo info = info_of(w, fa2.node(ja));
    const CutResult r = cut(w, in.loop, ja, out.loop, jb);
    for (std::uint32_t l : r.new_loops) drop_if_narrow(w, l, log);
    log.push_back({RepairKind::DamPlaced, info.record, info.id, unit_sphere().lonlat_from_param(0.5 * (in.x + out.x)),
                   uv_point_segment_metres(in.x, out.x, out.x, w.opt.radius)});
    ++placed;
    ++i;
  }
  return placed;
}

// Rebuilds a changed flat loop into curves (one per run of nodes with the same source,
// each dam a two-point curve) appended to `curves`.
// `ring`: the loop's nodes in order from its head.
WorkLoop rebuild(Work& w, const FlatLoop& f, const std::vector<std::uint32_t>& ring) {
  WorkLoop out;
  out.hole = f.hole;
  auto node = [&](std::size_t i) -> const Node& { return w.nodes[ring[i]]; };
  const std::size_t n = ring.size();
  std::size_t start = 0;
  while (start < n && node(start).src == node((start + n - 1) % n).src) ++start;
  if (start == n) start = 0;
  std::size_t i = start;
  do {
    const std::uint32_t src = node(i).src;
    WorkCurve c;
    c.periodic = false;
    if (src < w.n_curves) {
      c.open_boundary = w.curves[src].open_boundary;
      c.record = w.curves[src].record;
      c.id = w.curves[src].id;
    } else {
      c.record = w.dams[src - w.n_curves].record;
      c.id = w.dams[src - w.n_curves].id;
    }
    // The run's points counted first, so the curve's arrays are made at their size: grown
    // by doubling, a continent's curve held up to twice its points (the rebuild's peak).
    std::size_t run = 0, kept = 0;
    for (std::size_t j = i; run == 0 || (j != start && node(j).src == src); j = (j + 1) % n, ++run)
      kept += node(j).kept || j == i;
    c.full.reserve(run + 1);
    c.uv.reserve(run + 1);
    c.gamma.reserve(run + 1);
    c.keep.reserve(kept + 1);
    std::size_t j = i;
    do {
      const Node& nd = node(j);
      if (nd.kept || j == i) c.keep.push_back(static_cast<std::uint32_t>(c.full.size()));
      c.full.push_back(w.pool.ll(ring[j]));
      c.uv.push_back(w.pool.uv(ring[j]));
      c.gamma.push_back(w.pool.gamma(ring[j]));
      j = (j + 1) % n;
    } while (j != start && node(j).src == src);
    // The next curve's first point closes this one.
    c.keep.push_back(static_cast<std::uint32_t>(c.full.size()));
    c.full.push_back(w.pool.ll(ring[j]));
    c.uv.push_back(w.pool.uv(ring[j]));
    c.gamma.push_back(w.pool.gamma(ring[j]));
    out.curves.push_back(static_cast<std::uint32_t>(w.curves.size()));
    w.curves.push_back(std::move(c));
    i = j;
  } while (i != start);
  return out;
}

// The closest point of segment a-b to p among those x with dot(x - p, n) <= 0 (the half
// plane away from n); nullopt when the segment lies wholly on n's side.
std::optional<Vec2> closest_away(Vec2 p, Vec2 a, Vec2 b, Vec2 n) {
  const double fa = dot(a - p, n), fb = dot(b - p, n);
  if (fa > 0 && fb > 0) return std::nullopt;
  Vec2 lo = a, hi = b;
  if (fa > 0) lo = a + (fa / (fa - fb)) * (b - a);
  if (fb > 0) hi = a + (fa / (fa - fb)) * (b - a);
  return closest_on_segment(p, lo, hi);
}

struct Nearest {
  std::uint32_t loop = 0, seg = 0;
  Vec2 at{0, 0};
  double d2 = std::numeric_limits<double>::infinity();
};

// The nearest point of the live loops' kept segments to p (away from n when n is not 0).
Nearest nearest_coast(const Work& w, Vec2 p, Vec2 n) {
  Nearest best;
  for (std::uint32_t l = 0; l < w.flat.size(); ++l) {
    const FlatLoop& f = w.flat[l];
    if (f.dead) continue;
    const std::vector<Vec2> pts = polygon(f);
    for (std::uint32_t j = 0; j < pts.size(); ++j) {
      const Vec2 s0 = pts[j], s1 = pts[(j + 1) % pts.size()];
      const auto x = n == Vec2{0, 0} ? std::optional<Vec2>(closest_on_segment(p, s0, s1)) : closest_away(p, s0, s1, n);
      if (!x) continue;
      const double d2 = norm2(*x - p);
      if (d2 < best.d2) best = {l, j, *x, d2};
    }
  }
  return best;
}

// Whether p, whose nearest coast point is on kept segment j of f, lies in the water (on
// the left): at a vertex, on the left of both segments at a convex corner of the water,
// of either at a reflex one.
bool in_water(const FlatLoop& f, std::uint32_t j, Vec2 x, Vec2 p) {
  const std::size_t k = f.size();
  Vec2 u = f.p(j), v = f.p(j + 1), z = f.p(j + 2);
  if (x == f.p(j)) u = f.p(j + k - 1), v = f.p(j), z = f.p(j + 1);
  else if (!(x == f.p(j + 1))) return orient2d(u, v, p) == Sign::Positive;
  const bool l1 = orient2d(u, v, p) == Sign::Positive, l2 = orient2d(v, z, p) == Sign::Positive;
  return orient2d(u, v, z) == Sign::Positive ? (l1 && l2) : (l1 || l2);
}

// The two banks of the passage at p, from kept segment sa of loop la and sb of lb (the
// nearest coast on each side): each walks along its coast both ways while its next segment
// is within `reach` metres of p or within `across` metres of the other bank, and stops
// where it would meet the other (the head of an inlet). Bounded by the loops' sizes.
std::array<std::set<UvKey>, 2> banks_of(const Work& w, std::uint32_t la, std::uint32_t sa, std::uint32_t lb,
                                        std::uint32_t sb, Vec2 p, double reach, double across) {
  const std::uint32_t loop[2] = {la, lb};
  std::array<std::set<std::uint32_t>, 2> segs{std::set<std::uint32_t>{sa}, std::set<std::uint32_t>{sb}};
  std::uint32_t end[2][2] = {{sa, sa}, {sb, sb}};
  bool open[2][2] = {{true, true}, {true, true}};
  const double R = w.opt.radius;
  auto seg_m = [&](const FlatLoop& f, std::uint32_t j, const FlatLoop& g, std::uint32_t t) {
    const Vec2 a0 = f.p(j), a1 = f.p(j + 1), b0 = g.p(t), b1 = g.p(t + 1);
    return std::min({uv_point_segment_metres(a0, b0, b1, R), uv_point_segment_metres(a1, b0, b1, R),
                     uv_point_segment_metres(b0, a0, a1, R), uv_point_segment_metres(b1, a0, a1, R)});
  };
  const std::size_t bound = w.flat[la].size() + w.flat[lb].size() + 4;
  for (std::size_t step = 0; step < bound; ++step) {
    bool grew = false;
    for (int i = 0; i < 2; ++i)
      for (int d = 0; d < 2; ++d) {
        if (!open[i][d]) continue;
        const FlatLoop& f = w.flat[loop[i]];
        const FlatLoop& g = w.flat[loop[1 - i]];
        const auto k = static_cast<std::uint32_t>(f.size());
        const std::uint32_t next = d ? (end[i][d] + 1) % k : (end[i][d] + k - 1) % k;
        if (segs[i].count(next) || (loop[0] == loop[1] && segs[1 - i].count(next))) {
          open[i][d] = false;
          continue;
        }
        bool take = uv_point_segment_metres(p, f.p(next), f.p(next + 1), R) <= reach;
        for (auto it = segs[1 - i].begin(); !take && it != segs[1 - i].end(); ++it)
          take = seg_m(f, next, g, *it) <= across;
        if (!take) {
          open[i][d] = false;
          continue;
        }
        segs[i].insert(next);
        end[i][d] = next;
        grew = true;
      }
    if (!grew) break;
  }
  std::array<std::set<UvKey>, 2> out;
  for (int i = 0; i < 2; ++i)
    for (std::uint32_t j : segs[i]) out[i].insert(uv_key(w.flat[loop[i]].p(j)));
  return out;
}

// The passage at each KeepOpen point: errors for a point on land or with no coast across.
Result<bool> find_gates(Work& w, std::vector<RepairEntry>& log) {
  for (const geo::LonLat ll : w.opt.keep_open) {
    const Vec2 p = unit_sphere().param_from_lonlat(ll);
    const Nearest a = nearest_coast(w, p, {0, 0});
    auto fail = [&](std::string why) {
      return CoastError{coast_option_string(CoastOpt::KeepOpen), -1,
                        fmt::format("the KeepOpen point (lon {:.6f}, lat {:.6f}) {}", ll.lon, ll.lat, why), ll};
    };
    if (!std::isfinite(a.d2)) return fail("has no coastline near it");
    if (a.d2 == 0 || !in_water(w.flat[a.loop], a.seg, a.at, p))
      return fail("lies on land: put it in the water of the passage");
    const Nearest b = nearest_coast(w, p, a.at - p);
    if (!std::isfinite(b.d2)) return fail("has no coast across from its nearest coast: it is in no passage");
    Gate g;
    g.where = ll;
    g.width = chord(unit_sphere().lonlat_from_param(a.at), unit_sphere().lonlat_from_param(b.at), w.opt.radius);
    // The passage's own closing width: with width_at, min_width is only the search
    // radius (the widest width anywhere), which would hold far banks open.
    const double wide = std::max(passage_width_at(w.opt, ll), g.width);
    auto banks = banks_of(w, a.loop, a.seg, b.loop, b.seg, p, kKeepOpenReach * wide, kKeepOpenAcross * wide);
    g.bank[0] = std::move(banks[0]);
    g.bank[1] = std::move(banks[1]);
    const DamInfo info = info_of(w, w.flat[a.loop].node(a.seg));
    log.push_back({RepairKind::KeptOpen, info.record, info.id, ll, g.width});
    w.gates.push_back(std::move(g));
  }
  return true;
}

}  // namespace

double uv_point_segment_metres(Vec2 p, Vec2 a, Vec2 b, double radius) {
  const Vec2 f = closest_on_segment(p, a, b);
  return chord(unit_sphere().lonlat_from_param(p), unit_sphere().lonlat_from_param(f), radius);
}

Result<bool> close_passages(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops, const PassageOptions& opt,
                            std::vector<RepairEntry>& log, PassageStats* stats) {
  if (!(opt.min_width > 0) && opt.dams.empty() && opt.keep_open.empty()) return false;
  PassageStats local_stats;
  Work w{curves, curves.size(), opt, stats ? *stats : local_stats};
  flatten_loops(w, loops);
  // Flattening's per-curve scratch, freed among the pool's and the ropes' arrays, and each
  // round's (its segment lists, grid and near pairs) would stay resident under the next
  // round's, which come from elsewhere in the heap: the import's peak on the full-resolution
  // world (docs/kernel.md, "Memory").
  release_free_memory();
  if (auto g = find_gates(w, log); !g) return g.error();
  std::size_t vertices = 0;
  for (const FlatLoop& f : w.flat) vertices += f.dead ? 0 : f.size();
  for (const auto& [p, q] : opt.dams) {
    auto placed = place_dam(w, p, q, log);
    if (!placed) return placed.error();
    if (*placed == 0)
      return CoastError{
          coast_option_string(CoastOpt::Dams), -1,
          fmt::format("the dam from (lon {:.6f}, lat {:.6f}) to (lon {:.6f}, lat {:.6f}) crosses no water: "
                      "both ends and the line between them lie on land (or in one stretch of water)",
                      p.lon, p.lat, q.lon, q.lat),
          p};
  }
  // Each round closes at most one passage per loop, and every cut either drops water or
  // joins/splits loops; the bound only guards against a geometry that would not settle.
  if (opt.min_width > 0)
    for (std::size_t round = 0; round < 4 * vertices + 16; ++round) {
      if (!close_round(w, log)) break;
      release_free_memory();
    }
  bool changed = false;
  const std::size_t n_old = loops.size();
  // The rebuild reads only the rings: the polygons are freed first.
  for (FlatLoop& f : w.flat) f.rope = kNoRope;
  w.stats.kept_visits += w.ropes.work();
  w.ropes = KeptRopes();
  std::vector<std::vector<Vec2>>().swap(w.polys);
  std::vector<std::vector<double>>().swap(w.width);
  w.segments.clear();
  std::vector<char>().swap(w.remade);
  std::vector<Work::NearPair>().swap(w.near);
  // The loops to rebuild (changed in place, or made by cuts) and the curves of the loops
  // cut or rebuilt, whose points the rebuilt curves take over. Each such curve is freed as
  // soon as the last ring reading it is rebuilt (rings read the curves' points until then):
  // freeing them all at the end held every cut continent twice (the import's peak on the
  // full-resolution world).
  std::vector<char> rebuilt(w.flat.size(), 0);
  std::vector<std::uint32_t> unused;
  for (std::size_t l = 0; l < w.flat.size(); ++l) {
    const FlatLoop& f = w.flat[l];
    if (l < n_old) {
      if ((f.dead && !loops[l].dead) || (!f.dead && f.changed))
        unused.insert(unused.end(), loops[l].curves.begin(), loops[l].curves.end());
      rebuilt[l] = !f.dead && f.changed;
      continue;
    }
    rebuilt[l] = !f.dead;
  }
  std::vector<std::uint32_t> readers(w.n_curves, 0);   // per curve: the rings to rebuild that read it
  std::vector<std::uint32_t> ring;
  auto ring_of = [&](const FlatLoop& f) {
    ring.assign(1, f.head);
    w.walk(f.head, f.head, [&](std::uint32_t i) { ring.push_back(i); });
  };
  std::vector<std::uint32_t> read;   // the curves one ring reads, each once
  auto curves_read = [&]() {
    read.clear();
    for (std::uint32_t i : ring)
      if (w.nodes[i].curve != kAdded) read.push_back(w.nodes[i].curve);
    std::sort(read.begin(), read.end());
    read.erase(std::unique(read.begin(), read.end()), read.end());
  };
  for (std::size_t l = 0; l < w.flat.size(); ++l)
    if (rebuilt[l]) {
      ring_of(w.flat[l]);
      curves_read();
      for (std::uint32_t ci : read) ++readers[ci];
    }
  std::vector<char> is_unused(w.n_curves, 0);
  for (std::uint32_t ci : unused) is_unused[ci] = 1;
  // Freed curves' pages go back to the system every so often (kTrimBytes): the rebuilt
  // curves come from elsewhere in the heap, and the freed ones stayed resident under them.
  constexpr std::size_t kTrimBytes = std::size_t{32} << 20;
  std::size_t freed = 0;
  auto free_curve = [&](std::uint32_t ci) {
    WorkCurve& c = curves[ci];
    freed += c.full.capacity() * sizeof(geo::LonLat) + c.uv.capacity() * sizeof(Vec2) +
             c.gamma.capacity() * sizeof(double) + c.keep.capacity() * sizeof(std::uint32_t);
    std::vector<geo::LonLat>().swap(c.full);
    std::vector<Vec2>().swap(c.uv);
    std::vector<double>().swap(c.gamma);
    std::vector<std::uint32_t>().swap(c.keep);
  };
  // Nothing reads a dead loop's curves: those no ring reads go now.
  for (std::uint32_t ci : unused)
    if (readers[ci] == 0) free_curve(ci);
  for (std::size_t l = 0; l < w.flat.size(); ++l) {
    const FlatLoop& f = w.flat[l];
    if (l < n_old && f.dead && !loops[l].dead) loops[l].dead = true, changed = true;
    if (!rebuilt[l]) continue;
    ring_of(f);
    curves_read();
    // A loop changed in place (a dam's points inserted) is rebuilt where it was.
    if (l < n_old)
      loops[l] = rebuild(w, f, ring);
    else
      loops.push_back(rebuild(w, f, ring));
    changed = true;
    for (std::uint32_t ci : read)
      if (--readers[ci] == 0 && is_unused[ci]) free_curve(ci);
    if (freed >= kTrimBytes) release_free_memory(), freed = 0;
  }
  return changed;
}

}  // namespace sm::coast
