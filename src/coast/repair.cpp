// Repair of coarsened loops: local refinement toward the original shoreline, dropping
// islands below the accuracy, uniting overlaps and cutting slivers of the source data; the
// optional spline-hull pass; strait detection and island merging across straits.
#include "coast/repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <tuple>
#include <type_traits>

#include <fmt/format.h>

#include "base/parallel.h"
#include "coast/bridge_check.h"
#include "coast/intersections.h"
#include "exact/ring.h"
#include "coast/spline_check.h"
#include "exact/predicates.h"
#include "exact/segments.h"

namespace sm::coast {
namespace {

geo::LonLat uv_to_lonlat(Vec2 uv) { return geo::PolarSphere({0, 0, 0}, 1.0).lonlat_from_param(uv); }

// Full indices to put back on the segment leaving keep position k of curve c: the middle
// of the gap (bisection keeps the coarsening where it can), or, after kBisectRounds
// rounds, every original point of the gap (so the number of rounds stays small). Empty
// when the segment is already original.
constexpr std::size_t kBisectRounds = 4;
void refine_indices(const WorkCurve& c, std::uint32_t k, std::size_t round, std::vector<std::uint32_t>& out) {
  out.clear();
  const std::size_t n = c.full.size();
  std::size_t a = c.keep[k], b;
  if (k + 1 < c.keep.size())
    b = c.keep[k + 1];
  else if (c.periodic)
    b = n + c.keep[0];
  else
    return;
  if (b - a < 2) return;
  if (round < kBisectRounds) {
    out.push_back(static_cast<std::uint32_t>(((a + b) / 2) % n));
    return;
  }
  for (std::size_t i = a + 1; i < b; ++i) out.push_back(static_cast<std::uint32_t>(i % n));
}


double island_perimeter_m(const WorkCurve& c, double radius) {
  double p = 0;
  for (std::size_t i = 0; i < c.full.size(); ++i)
    p += chord(c.full[i], c.full[(i + 1) % c.full.size()], radius);
  return p;
}

// Removes the original points strictly between the segments leaving full indices a1 and
// a2 (a1 < a2) on the shorter side of the loop. Non-periodic curves can only lose the
// inside part (their ends are fixed). False when too little would remain.
bool cut_sliver(WorkCurve& c, std::uint32_t a1, std::uint32_t a2) {
  const std::size_t n = c.full.size();
  const std::size_t inner = a2 - a1;   // points a1+1 .. a2
  std::vector<char> drop(n, 0);
  if (!c.periodic || inner <= n - inner) {
    if (n - inner < 3) return false;
    for (std::size_t i = a1 + 1; i <= a2; ++i) drop[i] = 1;
  } else {
    if (inner < 3) return false;
    for (std::size_t i = 0; i < n; ++i) drop[i] = (i <= a1 || i > a2) ? 1 : 0;
  }
  std::vector<std::uint32_t> remap(n, 0xFFFFFFFFu);
  std::size_t m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (drop[i]) continue;
    remap[i] = static_cast<std::uint32_t>(m);
    c.full[m] = c.full[i];
    c.uv[m] = c.uv[i];
    c.gamma[m] = c.gamma[i];
    ++m;
  }
  c.full.resize(m);
  c.uv.resize(m);
  c.gamma.resize(m);
  std::vector<std::uint32_t> keep;
  for (std::uint32_t k : c.keep)
    if (remap[k] != 0xFFFFFFFFu) keep.push_back(remap[k]);
  // The two ends of the cut stay as vertices so the new segment joins them.
  for (std::size_t i : {std::size_t{a1}, std::size_t{a2} + 1})
    if (i < n && remap[i] != 0xFFFFFFFFu) keep.push_back(remap[i]);
  std::sort(keep.begin(), keep.end());
  keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
  c.keep = std::move(keep);
  return c.keep.size() >= 3 || !c.periodic;
}

// A loop of several curves (the pieces a binned or clipped source is read in, joined end
// to end) whose source data meets itself across the end of a piece: the sliver between
// segment a of the loop's curve i and segment b of its curve j is cut out the way
// cut_sliver cuts it within one curve, on the side of the loop holding fewer points: going
// forward along the loop from (i, a) to (j, b), or from (j, b) to (i, a) (cyclically).
// Going from (i, a) to (j, b), curve i keeps its points up to a and ends on point b + 1 of
// curve j, where curve j now starts; the curves between them leave the loop, and so does
// curve j when only that point is left of it. Every curve keeps both its end points, so the
// loop stays closed. False (nothing changed) when the cut side holds the region's box or
// fewer than three points would remain. `dropped` receives the curves that left the loop.
bool cut_sliver_across(std::vector<WorkCurve>& curves, WorkLoop& loop, std::size_t i, std::uint32_t a, std::size_t j,
                       std::uint32_t b, std::vector<std::uint32_t>& dropped) {
  const std::size_t nl = loop.curves.size();
  if (i == j || i >= nl || j >= nl) return false;
  std::size_t total = 0;   // points of the loop, each curve's end counted as the next one's start
  for (std::uint32_t ci : loop.curves) total += curves[ci].full.size() - 1;
  // The points cut going forward from (i, a) to (j, b): i's after a, the curves between,
  // j's up to b + 1 (j's first point being i's last), the rest of the loop the other way.
  auto forward = [&](std::size_t from, std::uint32_t at, std::size_t to, std::uint32_t upto) {
    std::size_t n = (curves[loop.curves[from]].full.size() - 1 - at) + upto;
    for (std::size_t k = (from + 1) % nl; k != to; k = (k + 1) % nl) n += curves[loop.curves[k]].full.size() - 1;
    return n;
  };
  std::size_t cut = forward(i, a, j, b);
  if (cut > total - cut) {
    std::swap(i, j);
    std::swap(a, b);
    cut = total - cut;
  }
  WorkCurve& A = curves[loop.curves[i]];
  WorkCurve& B = curves[loop.curves[j]];
  if (A.periodic || B.periodic || a + 1 >= A.full.size() || b + 1 >= B.full.size()) return false;
  if (A.open_boundary || B.open_boundary) return false;
  for (std::size_t k = (i + 1) % nl; k != j; k = (k + 1) % nl)
    if (curves[loop.curves[k]].open_boundary) return false;
  if (cut >= total || total - cut < 3) return false;
  const bool b_gone = b + 2 == B.full.size();   // only B's end would be left of it
  // A: its points 0 .. a, then B's point b + 1.
  A.full.resize(a + 1);
  A.uv.resize(a + 1);
  A.gamma.resize(a + 1);
  A.full.push_back(B.full[b + 1]);
  A.uv.push_back(B.uv[b + 1]);
  A.gamma.push_back(B.gamma[b + 1]);
  std::erase_if(A.keep, [a](std::uint32_t k) { return k > a; });
  if (A.keep.empty() || A.keep.back() != a) A.keep.push_back(a);   // the cut's two ends stay vertices
  A.keep.push_back(a + 1);
  // B: its points b + 1 .. end.
  if (!b_gone) {
    B.full.erase(B.full.begin(), B.full.begin() + b + 1);
    B.uv.erase(B.uv.begin(), B.uv.begin() + b + 1);
    B.gamma.erase(B.gamma.begin(), B.gamma.begin() + b + 1);
    std::vector<std::uint32_t> keep{0};
    for (std::uint32_t k : B.keep)
      if (k > b + 1) keep.push_back(k - b - 1);
    B.keep = std::move(keep);
  }
  std::vector<char> leaves(nl, 0);
  for (std::size_t k = (i + 1) % nl; k != j; k = (k + 1) % nl) leaves[k] = 1;
  if (b_gone) leaves[j] = 1;
  std::vector<std::uint32_t> rest;
  for (std::size_t k = 0; k < nl; ++k) (leaves[k] ? dropped : rest).push_back(loop.curves[k]);
  loop.curves = std::move(rest);
  return true;
}

// Unites two islands whose source outlines cross (properly, at 2k points): the boundary of
// the union of the two land polygons (both counter-clockwise, land inside). Walking from a
// crossing where A leaves B: A up to the next crossing along A, then B up to the next
// crossing along B, and so on. Every hit must be a proper crossing between original
// segments and the walk must visit every crossing (a single outline); else false.
bool unite_islands(std::vector<WorkCurve>& curves, WorkLoop& la, WorkLoop& lb, const std::vector<Vec2>& pa,
                   const std::vector<LoopVertexRef>& ra, const std::vector<Vec2>& pb,
                   const std::vector<LoopVertexRef>& rb, const std::vector<const SegmentHit*>& hits, bool a_first) {
  WorkCurve& A = curves[la.curves[0]];
  const WorkCurve& B = curves[lb.curves[0]];
  if (ring_orientation(pa) != Sign::Positive || ring_orientation(pb) != Sign::Positive) return false;
  struct X {
    std::size_t ia, ib;   // full index starting the crossed original segment of A, of B
    double ta, tb;        // position along those segments
    Vec2 p;
    bool a_exits;         // A leaves B's land here
  };
  std::vector<X> xs;
  for (const SegmentHit* h : hits) {
    if (h->kind != HitKind::Cross) return false;
    const std::uint32_t sa = a_first ? h->seg_a : h->seg_b, sb = a_first ? h->seg_b : h->seg_a;
    const Vec2 a0 = pa[sa], a1 = pa[(sa + 1) % pa.size()], b0 = pb[sb], b1 = pb[(sb + 1) % pb.size()];
    const std::size_t ia = A.keep[ra[sa].k], ib = B.keep[rb[sb].k];
    if ((ia + 1) % A.full.size() != A.keep[(ra[sa].k + 1) % A.keep.size()]) return false;   // not original
    if ((ib + 1) % B.full.size() != B.keep[(rb[sb].k + 1) % B.keep.size()]) return false;
    const Vec2 r = a1 - a0, q = b1 - b0;
    const double den = cross(r, q);
    if (den == 0) return false;
    X x;
    x.ia = ia;
    x.ib = ib;
    x.ta = cross(b0 - a0, q) / den;
    x.tb = cross(b0 - a0, r) / den;
    x.p = a0 + x.ta * r;
    x.a_exits = orient2d(b0, b1, a1) == Sign::Negative;
    xs.push_back(x);
  }
  const std::size_t m = xs.size();
  if (m < 2 || m % 2) return false;
  std::vector<std::size_t> by_a(m), by_b(m), pos_a(m), pos_b(m);
  for (std::size_t i = 0; i < m; ++i) by_a[i] = by_b[i] = i;
  std::sort(by_a.begin(), by_a.end(),
            [&](std::size_t i, std::size_t j) { return std::tie(xs[i].ia, xs[i].ta) < std::tie(xs[j].ia, xs[j].ta); });
  std::sort(by_b.begin(), by_b.end(),
            [&](std::size_t i, std::size_t j) { return std::tie(xs[i].ib, xs[i].tb) < std::tie(xs[j].ib, xs[j].tb); });
  for (std::size_t i = 0; i < m; ++i) pos_a[by_a[i]] = i, pos_b[by_b[i]] = i;
  std::size_t start = m;
  for (std::size_t i = 0; i < m && start == m; ++i)
    if (xs[by_a[i]].a_exits) start = by_a[i];
  if (start == m) return false;
  std::vector<char> kept_a(A.full.size(), 0), kept_b(B.full.size(), 0);
  for (auto i : A.keep) kept_a[i] = 1;
  for (auto i : B.keep) kept_b[i] = 1;
  WorkCurve M;
  M.periodic = true;
  M.record = A.record;
  M.id = A.id;
  auto add = [&M](geo::LonLat ll, Vec2 uv, double g, bool keep) {
    if (keep) M.keep.push_back(static_cast<std::uint32_t>(M.full.size()));
    M.full.push_back(ll);
    M.uv.push_back(uv);
    M.gamma.push_back(g);
  };
  // Original points strictly after crossing `from` up to the segment start of `to`.
  auto run = [&](const WorkCurve& c, const std::vector<char>& kept, std::size_t i_from, double t_from, std::size_t i_to,
                 double t_to) {
    const std::size_t n = c.full.size();
    std::size_t count = (i_to + n - i_from) % n;
    if (count == 0 && t_to <= t_from) count = n;
    for (std::size_t s = 1; s <= count; ++s) {
      const std::size_t i = (i_from + s) % n;
      add(c.full[i], c.uv[i], c.gamma[i], kept[i] != 0);
    }
  };
  std::vector<char> seen(m, 0);
  std::size_t x = start;
  bool on_a = true;
  for (std::size_t guard = 0; guard <= 2 * m; ++guard) {
    if (on_a && seen[x]) break;
    const X& cx = xs[x];
    const double g = std::min(A.gamma[cx.ia], B.gamma[cx.ib]);
    if (on_a) {
      seen[x] = 1;
      add(geo::PolarSphere({0, 0, 0}, 1.0).lonlat_from_param(cx.p), cx.p, g, true);
      const std::size_t nx = by_a[(pos_a[x] + 1) % m];
      if (xs[nx].a_exits) return false;   // must enter B next
      run(A, kept_a, cx.ia, cx.ta, xs[nx].ia, xs[nx].ta);
      x = nx;
      on_a = false;
    } else {
      seen[x] = 1;
      add(geo::PolarSphere({0, 0, 0}, 1.0).lonlat_from_param(cx.p), cx.p, g, true);
      const std::size_t nx = by_b[(pos_b[x] + 1) % m];
      run(B, kept_b, cx.ib, cx.tb, xs[nx].ib, xs[nx].tb);
      x = nx;
      on_a = true;
    }
  }
  if (std::count(seen.begin(), seen.end(), 1) != static_cast<long>(m) || M.keep.size() < 3) return false;
  A = std::move(M);
  lb.dead = true;
  return true;
}

// An island A whose source outline crosses a cut coastline piece c of a water loop W
// (regional data: an islet overlapping the mainland) at exactly two places: the part of
// c between the crossings, which runs under the island, is replaced by the island's arc
// that lies in the water, so the island becomes part of the mainland.
bool unite_island_with_coast(std::vector<WorkCurve>& curves, WorkLoop& island, const std::vector<Vec2>& pa,
                             const std::vector<LoopVertexRef>& ra, const std::vector<Vec2>& pw,
                             const std::vector<LoopVertexRef>& rw, const std::vector<const SegmentHit*>& hits,
                             bool island_first) {
  if (hits.size() != 2) return false;
  WorkCurve& A = curves[island.curves[0]];
  struct X {
    std::size_t ia, ic;
    double ta, tc;
    Vec2 p;
  };
  std::vector<X> xs;
  std::uint32_t curve_c = 0xFFFFFFFFu;
  for (const SegmentHit* h : hits) {
    if (h->kind != HitKind::Cross) return false;
    const std::uint32_t sa = island_first ? h->seg_a : h->seg_b, sw = island_first ? h->seg_b : h->seg_a;
    const LoopVertexRef wa = ra[sa], ww = rw[sw];
    if (curve_c != 0xFFFFFFFFu && ww.curve != curve_c) return false;
    curve_c = ww.curve;
    const WorkCurve& c = curves[ww.curve];
    if (c.open_boundary || (!c.periodic && ww.k + 1 >= c.keep.size())) return false;
    const std::size_t ia = A.keep[wa.k], ic = c.keep[ww.k];
    if ((ia + 1) % A.full.size() != A.keep[(wa.k + 1) % A.keep.size()] ||
        (ic + 1) % c.full.size() != c.keep[(ww.k + 1) % c.keep.size()])
      return false;   // both crossed segments must be original
    const Vec2 a0 = pa[sa], a1 = pa[(sa + 1) % pa.size()], c0 = pw[sw], c1 = pw[(sw + 1) % pw.size()];
    const Vec2 r = a1 - a0, q = c1 - c0;
    const double den = cross(r, q);
    if (den == 0) return false;
    X x{ia, ic, cross(c0 - a0, q) / den, cross(c0 - a0, r) / den, {}};
    x.p = a0 + x.ta * r;
    xs.push_back(x);
  }
  if (std::tie(xs[1].ic, xs[1].tc) < std::tie(xs[0].ic, xs[0].tc)) std::swap(xs[0], xs[1]);
  WorkCurve& c = curves[curve_c];
  const std::size_t nc = c.full.size();
  // Which part of c runs under the island: between the crossings (F) or, for a periodic
  // curve, the rest (R). The part under the island is replaced by its arc in the water.
  const Vec2 probe_f = xs[0].ic == xs[1].ic ? 0.5 * (xs[0].p + xs[1].p) : c.uv[xs[0].ic + 1];
  bool replace_f = point_in_ring(pa, probe_f);
  if (!replace_f) {
    if (!c.periodic) return false;
    const Vec2 probe_r = xs[0].ic == xs[1].ic ? c.uv[(xs[1].ic + 1) % nc] : c.uv[(xs[1].ic + 1) % nc];
    if (!point_in_ring(pa, probe_r)) return false;
  }
  // Arc of the island in the water from crossing `from` to crossing `to`.
  const std::size_t n = A.full.size();
  auto water_arc = [&](const X& from, const X& to, std::vector<std::size_t>& arc) {
    arc.clear();
    if (point_in_ring(pw, A.uv[(from.ia + 1) % n])) {
      for (std::size_t i = (from.ia + 1) % n;; i = (i + 1) % n) {
        arc.push_back(i);
        if (i == to.ia || arc.size() > n) break;
      }
    } else {
      if (!point_in_ring(pw, A.uv[from.ia])) return false;
      for (std::size_t i = from.ia; i != to.ia && arc.size() <= n; i = (i + n - 1) % n) arc.push_back(i);
      arc.push_back((to.ia + 1) % n);
    }
    return arc.size() <= n;
  };
  std::vector<std::size_t> arc;
  std::vector<char> kept_c(nc, 0);
  for (auto i : c.keep) kept_c[i] = 1;
  WorkCurve M = c;
  M.full.clear();
  M.uv.clear();
  M.gamma.clear();
  M.keep.clear();
  auto add = [&M](geo::LonLat ll, Vec2 uv, double g, bool keep) {
    if (keep) M.keep.push_back(static_cast<std::uint32_t>(M.full.size()));
    M.full.push_back(ll);
    M.uv.push_back(uv);
    M.gamma.push_back(g);
  };
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  auto add_x = [&](const X& x) { add(ps.lonlat_from_param(x.p), x.p, c.gamma[x.ic], true); };
  auto add_c = [&](std::size_t i) { add(c.full[i], c.uv[i], c.gamma[i], kept_c[i] != 0); };
  if (replace_f) {   // c[0..ic0], X0, water arc X0 -> X1, X1, c[ic1+1..]
    if (!water_arc(xs[0], xs[1], arc)) return false;
    for (std::size_t i = 0; i <= xs[0].ic; ++i) add_c(i);
    add_x(xs[0]);
    for (std::size_t i : arc) add(A.full[i], A.uv[i], A.gamma[i], true);
    add_x(xs[1]);
    for (std::size_t i = xs[1].ic + 1; i < nc; ++i) add_c(i);
  } else {           // periodic: c[ic0+1..ic1], X1, water arc X1 -> X0, X0
    if (!water_arc(xs[1], xs[0], arc)) return false;
    for (std::size_t i = xs[0].ic + 1; i <= xs[1].ic; ++i) add_c(i);
    add_x(xs[1]);
    for (std::size_t i : arc) add(A.full[i], A.uv[i], A.gamma[i], true);
    add_x(xs[0]);
  }
  if (M.keep.size() < 3) return false;
  c = std::move(M);
  island.dead = true;
  return true;
}

// Two pieces of B-spline closer than this fraction of gamma count as meeting: far below
// anything a mesh of size gamma resolves, far above rounding.
constexpr double kSplineTolerance = 1e-3;

// What a repair round changed, for the next round's intersection test: pairs of two
// segments unchanged since they were last tested keep their verdict (no hit, or they would
// be marked), so only pairs with a marked segment are tested again. A loop cut or united
// is marked whole; a point put back marks the segments that end at it; a hit marks its two
// segments (left alone, it is found again). Points are named by curve and full index,
// which a round's changes other than the whole-loop ones keep.
//
// The same marks are gathered a second time from one spline pass to the next (`spline`):
// a span is the curve on four consecutive control points, so two spans none of whose
// points changed since the last pass keep that pass's verdict (apart, or the pair was
// found and its spans marked again: `touch_span`).
struct RoundChanges {
  struct Marks {
    std::vector<char> whole;                        // per loop: every segment
    std::vector<std::vector<std::uint32_t>> at;     // per curve: full indices of marked points
  };
  Marks round, spline;

  RoundChanges(std::size_t loops, std::size_t curves)
      : round{std::vector<char>(loops, 1), std::vector<std::vector<std::uint32_t>>(curves)}, spline(round) {}
  void touch(std::uint32_t curve, std::uint32_t full) {
    round.at[curve].push_back(full);
    spline.at[curve].push_back(full);
  }
  void whole_loop(std::size_t l) { round.whole[l] = spline.whole[l] = 1; }
  // A curve renumbered (a sliver cut out, a segment split): the loops using it, whole.
  void whole_curve(const std::vector<WorkLoop>& loops, std::uint32_t curve) {
    for (std::size_t l = 0; l < loops.size(); ++l)
      for (std::uint32_t c : loops[l].curves)
        if (c == curve) whole_loop(l);
  }
  void touch_segment(const std::vector<WorkCurve>& curves, const std::vector<LoopVertexRef>& refs, std::uint32_t s) {
    for (const LoopVertexRef r : {refs[s], refs[(s + 1) % refs.size()]}) touch(r.curve, curves[r.curve].keep[r.k]);
  }
  // A span found by a spline pass is tested again by the next one: its point s marked
  // (the span following segment s holds point s).
  void touch_span(const std::vector<WorkCurve>& curves, const std::vector<LoopVertexRef>& refs, std::uint32_t s) {
    const LoopVertexRef r = refs[s];
    spline.at[r.curve].push_back(curves[r.curve].keep[r.k]);
  }
  // Per loop and segment of the polygons as they are now: marked or not. The round's marks
  // are cleared for the next round.
  void active(const std::vector<WorkCurve>& curves, const std::vector<WorkLoop>& loops,
              const std::vector<std::vector<LoopVertexRef>>& refs, std::vector<std::vector<char>>& out) {
    marked_segments(round, curves, loops, refs, out);
  }
  // Per loop and segment: whether the span following it holds a point marked since the
  // last spline pass (segment s-1, s or s+1 marked: the span on points s-1 .. s+2, which a
  // loop of pieces clamps inside its piece). The spline marks are cleared.
  void spline_active(const std::vector<WorkCurve>& curves, const std::vector<WorkLoop>& loops,
                     const std::vector<std::vector<LoopVertexRef>>& refs, std::vector<std::vector<char>>& out) {
    marked_segments(spline, curves, loops, refs, out);
    std::vector<char> seg;
    for (std::vector<char>& a : out) {
      const std::size_t n = a.size();
      if (n == 0 || std::all_of(a.begin(), a.end(), [](char c) { return c != 0; })) continue;
      seg = a;
      for (std::size_t s = 0; s < n; ++s)
        a[s] = static_cast<char>(seg[(s + n - 1) % n] | seg[s] | seg[(s + 1) % n]);
    }
  }

 private:
  static void marked_segments(Marks& m, const std::vector<WorkCurve>& curves, const std::vector<WorkLoop>& loops,
                              const std::vector<std::vector<LoopVertexRef>>& refs,
                              std::vector<std::vector<char>>& out) {
    out.resize(loops.size());
    for (auto& a : m.at) {
      std::sort(a.begin(), a.end());
      a.erase(std::unique(a.begin(), a.end()), a.end());
    }
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const std::size_t n = refs[l].size();
      out[l].assign(n, m.whole[l]);
      if (m.whole[l] || n == 0) continue;
      bool any = false;
      for (std::uint32_t ci : loops[l].curves) any = any || !m.at[ci].empty();
      if (!any) continue;
      for (std::size_t v = 0; v < n; ++v) {
        const LoopVertexRef r = refs[l][v];
        const std::vector<std::uint32_t>& a = m.at[r.curve];
        if (a.empty() || !std::binary_search(a.begin(), a.end(), curves[r.curve].keep[r.k])) continue;
        out[l][v] = 1;               // the segment leaving the point
        out[l][(v + n - 1) % n] = 1;   // and the one reaching it
      }
    }
    std::fill(m.whole.begin(), m.whole.end(), 0);
    for (auto& a : m.at) a.clear();
  }
};

// Puts original points (curve, full index) back among their curves' kept points, marks
// each for the next round (the two segments that end at it are new) and logs one entry of
// `kind` a curve, at its first point put back.
void put_back_points(std::vector<WorkCurve>& curves, std::vector<std::pair<std::uint32_t, std::uint32_t>>& inserts,
                     RepairKind kind, RoundChanges& changes, std::vector<RepairEntry>& log) {
  std::sort(inserts.begin(), inserts.end());
  inserts.erase(std::unique(inserts.begin(), inserts.end()), inserts.end());
  for (std::size_t i = 0; i < inserts.size();) {
    const std::uint32_t ci = inserts[i].first;
    WorkCurve& c = curves[ci];
    std::size_t j = i;
    while (j < inserts.size() && inserts[j].first == ci) {
      c.keep.push_back(inserts[j].second);
      changes.touch(ci, inserts[j++].second);
    }
    std::sort(c.keep.begin(), c.keep.end());
    c.keep.erase(std::unique(c.keep.begin(), c.keep.end()), c.keep.end());
    log.push_back({kind, c.record, c.id, c.full[inserts[i].second], static_cast<double>(j - i)});
    i = j;
  }
}

// One pass of the spline check on intersection-free polygons. Puts original points back on
// the control segments around spans whose curves cross (or come within the tolerance), or
// splits those segments; returns true when nothing was changed (done), after logging the
// places left. With !may_fix (no repair rounds left) every place found is logged. What it
// changed is marked in `changes`.
bool spline_pass(std::vector<WorkCurve>& curves, const std::vector<WorkLoop>& loops,
                 const std::vector<std::vector<Vec2>>& polys, const std::vector<std::vector<LoopVertexRef>>& refs,
                 std::size_t round, const RepairOptions& opt, bool may_fix, std::vector<RepairEntry>& log,
                 RoundChanges& changes) {
  const double radius = opt.radius;
  std::vector<std::vector<std::uint32_t>> starts(loops.size());
  std::vector<std::vector<double>> tol(loops.size());
  std::vector<std::vector<char>> active;
  changes.spline_active(curves, loops, refs, active);
  std::vector<SplineLoop> sl(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& r = refs[l];
    for (std::uint32_t i = 0; i < r.size(); ++i) {
      if (i == 0 || r[i].curve != r[i - 1].curve) starts[l].push_back(i);
      // gamma in metres to (u,v): divided by the conformal factor 2R / (1 + |uv|^2).
      const WorkCurve& c = curves[r[i].curve];
      const Vec2 uv = polys[l][i];
      tol[l].push_back(kSplineTolerance * c.gamma[c.keep[r[i].k]] * (1.0 + norm2(uv)) / (2.0 * radius));
    }
    sl[l].pts = polys[l];
    sl[l].piece_start = starts[l];
    sl[l].periodic = loops[l].curves.size() == 1 && !loops[l].dead && curves[loops[l].curves[0]].periodic;
    sl[l].tol = tol[l];
    sl[l].active = active[l];
  }
  const std::vector<HullOverlap> over = find_spline_crossings(sl, opt.threads);
  if (over.empty()) return true;
  for (const HullOverlap& o : over) {   // found again by the next pass unless mended
    changes.touch_span(curves, refs[o.loop_a], o.seg_a);
    changes.touch_span(curves, refs[o.loop_b], o.seg_b);
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> inserts, splits;   // (curve, full index)
  std::vector<std::uint32_t> idx;
  std::vector<const HullOverlap*> stuck;
  for (const HullOverlap& o : over) {
    if (!may_fix) {
      stuck.push_back(&o);
      continue;
    }
    bool any = false;
    const std::size_t first_split = splits.size();
    for (const auto& [l, s] :
         {std::pair{o.loop_a, o.seg_a}, std::pair{o.loop_b, o.seg_b}}) {  // inserts are made unique
      const auto n = static_cast<std::uint32_t>(polys[l].size());
      for (std::uint32_t d : {n - 1, 0u, 1u}) {   // the span's control segments s-1, s, s+1
        const std::uint32_t v = (s + d) % n;
        const LoopVertexRef r = refs[l][v];
        const WorkCurve& c = curves[r.curve];
        refine_indices(c, r.k, round, idx);
        for (std::uint32_t i : idx) inserts.push_back({r.curve, i});
        any |= !idx.empty();
        // An original segment longer than a few tolerances can still be split at its
        // middle: the spline follows its control polygon closer with every point added.
        const bool has_segment = c.periodic || r.k + 1 < c.keep.size();
        if (idx.empty() && has_segment && norm(polys[l][(v + 1) % n] - polys[l][v]) > 4.0 * tol[l][v])
          splits.push_back({r.curve, c.keep[r.k]});
      }
    }
    if (!any && splits.size() == first_split) stuck.push_back(&o);
  }
  if (inserts.empty() && splits.empty()) {
    // One warning per pair of loops.
    std::uint32_t la = 0xFFFFFFFFu, lb = 0xFFFFFFFFu;
    for (const HullOverlap* o : stuck) {
      if (o->loop_a == la && o->loop_b == lb) continue;
      la = o->loop_a;
      lb = o->loop_b;
      const WorkCurve& c = curves[refs[la][o->seg_a].curve];
      log.push_back({RepairKind::SplineMayCross, c.record, c.id, uv_to_lonlat(o->where), 0});
    }
    return true;
  }
  // Points put back first (full indices unchanged), then the splits, which renumber.
  put_back_points(curves, inserts, RepairKind::SplineHull, changes, log);
  std::sort(splits.begin(), splits.end());
  splits.erase(std::unique(splits.begin(), splits.end()), splits.end());
  for (std::size_t i = splits.size(); i > 0;) {
    const std::uint32_t ci = splits[i - 1].first;
    WorkCurve& c = curves[ci];
    changes.whole_curve(loops, ci);
    std::size_t j = i;
    while (j > 0 && splits[j - 1].first == ci) {   // from the last index down: earlier ones stay valid
      const std::uint32_t a = splits[--j].second;
      const auto n = static_cast<std::uint32_t>(c.full.size());
      const std::uint32_t b = (a + 1) % n;
      const Vec2 uv = 0.5 * (c.uv[a] + c.uv[b]);
      c.full.insert(c.full.begin() + a + 1, uv_to_lonlat(uv));
      c.uv.insert(c.uv.begin() + a + 1, uv);
      c.gamma.insert(c.gamma.begin() + a + 1, std::min(c.gamma[a], c.gamma[b]));
      for (std::uint32_t& k : c.keep) k += k > a ? 1 : 0;
      c.keep.insert(std::upper_bound(c.keep.begin(), c.keep.end(), a), a + 1);
    }
    log.push_back({RepairKind::SplineHull, c.record, c.id, c.full[splits[j].second + 1], static_cast<double>(i - j)});
    i = j;
  }
  return false;
}

double mean_gamma(const WorkCurve& c) {
  double g = 0;
  for (double x : c.gamma) g += x;
  return c.gamma.empty() ? 0 : g / static_cast<double>(c.gamma.size());
}

// The loops being repaired, as polygons with their vertices' origins, and what changed since
// they were last checked (RoundChanges): pairs of unchanged segments keep their earlier
// (clean) verdict.
struct LoopRepair {
  std::vector<WorkCurve>& curves;
  std::vector<WorkLoop>& loops;
  std::vector<RepairEntry>& log;
  std::vector<std::vector<Vec2>> polys;
  std::vector<std::vector<LoopVertexRef>> refs;
  RoundChanges changes;
  std::vector<std::vector<char>> active;   // per loop and segment: tested this round
  std::vector<char> curve_changed;         // per curve: in a loop marked whole (rebuild_polygons)

  LoopRepair(std::vector<WorkCurve>& c, std::vector<WorkLoop>& l, std::vector<RepairEntry>& lg)
      : curves(c), loops(l), log(lg), polys(l.size()), refs(l.size()), changes(l.size(), c.size()) {}

  // The polygons of the loops a round changed made again, the others' kept: a change to a
  // curve's points or keep list marks the loop whole or the curve's points (RoundChanges),
  // so a loop none of whose curves is marked and which is not marked whole has the polygon
  // it had (making every loop's again each round was a gather through the keep lists of the
  // whole coast, 17 rounds at 3 km on the full GSHHG). A curve of a loop marked whole is
  // taken as changed in every loop that uses it. Called before the round's marks are read
  // (and cleared) by changes.active.
  void rebuild_polygons() {
    const RoundChanges::Marks& m = changes.round;
    curve_changed.assign(curves.size(), 0);
    for (std::size_t l = 0; l < loops.size(); ++l)
      if (m.whole[l])
        for (std::uint32_t ci : loops[l].curves) curve_changed[ci] = 1;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (loops[l].dead) {
        polys[l].clear();
        refs[l].clear();
        continue;
      }
      bool dirty = m.whole[l] != 0;
      for (std::size_t k = 0; k < loops[l].curves.size() && !dirty; ++k) {
        const std::uint32_t ci = loops[l].curves[k];
        dirty = curve_changed[ci] || !m.at[ci].empty();
      }
      if (dirty) loop_polygon(curves, loops[l], polys[l], &refs[l]);
    }
  }

  void mark_loops_using(std::uint32_t ci) { changes.whole_curve(loops, ci); }
};

// 1. Puts original points back on every offending segment that has some. True when some
// were put back; the hits whose two segments are both original are listed in `stuck`.
bool put_back_original_points(LoopRepair& r, const std::vector<SegmentHit>& hits, std::size_t round,
                              std::vector<const SegmentHit*>& stuck) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> inserts;   // (curve, full index)
  std::vector<std::uint32_t> idx;
  for (const SegmentHit& h : hits) {
    bool any = false;
    for (const auto& [l, s] : {std::pair{h.loop_a, h.seg_a}, std::pair{h.loop_b, h.seg_b}}) {
      const LoopVertexRef ref = r.refs[l][s];   // the segment's first vertex owns it
      refine_indices(r.curves[ref.curve], ref.k, round, idx);
      for (std::uint32_t i : idx) inserts.push_back({ref.curve, i});
      any |= !idx.empty();
    }
    if (!any) stuck.push_back(&h);
  }
  if (inserts.empty()) return false;
  put_back_points(r.curves, inserts, RepairKind::Refined, r.changes, r.log);
  return true;
}

// 2. Original data still meets: drops an island below the accuracy (one per stuck hit).
bool drop_small_islands(LoopRepair& r, const std::vector<const SegmentHit*>& stuck, double radius) {
  bool dropped = false;
  for (const SegmentHit* h : stuck) {
    for (std::uint32_t l : {h->loop_a, h->loop_b}) {
      WorkLoop& loop = r.loops[l];
      if (loop.dead || !loop.hole || loop.curves.size() != 1) continue;
      const WorkCurve& c = r.curves[loop.curves[0]];
      if (!c.periodic || island_perimeter_m(c, radius) >= 5.0 * mean_gamma(c)) continue;
      loop.dead = true;
      dropped = true;
      r.log.push_back({RepairKind::DroppedIsland, c.record, c.id, uv_to_lonlat(h->where), 0});
      break;
    }
  }
  return dropped;
}

// 2b. Unites two islands whose source outlines overlap, or an island with the water loop
// it overlaps; each loop at most once per round.
bool unite_overlapping_islands(LoopRepair& r, const std::vector<const SegmentHit*>& stuck) {
  std::vector<WorkCurve>& curves = r.curves;
  std::vector<WorkLoop>& loops = r.loops;
  bool united = false;
  std::vector<const SegmentHit*> by_pair(stuck.begin(), stuck.end());
  std::stable_sort(by_pair.begin(), by_pair.end(), [](const SegmentHit* x, const SegmentHit* y) {
    return std::pair(x->loop_a, x->loop_b) < std::pair(y->loop_a, y->loop_b);
  });
  std::vector<char> used(loops.size(), 0);
  for (std::size_t i = 0; i < by_pair.size();) {
    const std::uint32_t a = by_pair[i]->loop_a, b = by_pair[i]->loop_b;
    std::size_t j = i;
    while (j < by_pair.size() && by_pair[j]->loop_a == a && by_pair[j]->loop_b == b) ++j;
    const std::vector<const SegmentHit*> pair(by_pair.begin() + static_cast<long>(i),
                                              by_pair.begin() + static_cast<long>(j));
    i = j;
    if (a != b && !used[a] && !used[b] && !loops[a].dead && !loops[b].dead && loops[a].hole != loops[b].hole) {
      const std::uint32_t isl = loops[a].hole ? a : b, water = loops[a].hole ? b : a;
      const WorkLoop& il = loops[isl];
      if (il.curves.size() == 1 && curves[il.curves[0]].periodic) {   // an island against water
        const WorkCurve& ci = curves[il.curves[0]];
        const std::size_t rec = ci.record;
        const std::int64_t id = ci.id;
        if (unite_island_with_coast(curves, loops[isl], r.polys[isl], r.refs[isl], r.polys[water], r.refs[water],
                                    pair, isl == a)) {
          used[a] = used[b] = 1;
          r.changes.whole_loop(a);
          r.changes.whole_loop(b);
          united = true;
          r.log.push_back({RepairKind::UnitedIslands, rec, id, uv_to_lonlat(pair.front()->where), 0});
        }
      }
      continue;
    }
    if (a == b || used[a] || used[b] || loops[a].dead || loops[b].dead || !loops[a].hole || !loops[b].hole ||
        loops[a].curves.size() != 1 || loops[b].curves.size() != 1 || !curves[loops[a].curves[0]].periodic ||
        !curves[loops[b].curves[0]].periodic)
      continue;
    const WorkCurve& cb = curves[loops[b].curves[0]];
    const std::size_t rec_b = cb.record;
    const std::int64_t id_b = cb.id;
    if (unite_islands(curves, loops[a], loops[b], r.polys[a], r.refs[a], r.polys[b], r.refs[b], pair, true)) {
      used[a] = used[b] = 1;
      r.changes.whole_loop(a);
      r.changes.whole_loop(b);
      united = true;
      r.log.push_back({RepairKind::UnitedIslands, rec_b, id_b, uv_to_lonlat(pair.front()->where), 0});
    }
  }
  return united;
}

// 3. A loop that meets itself on original data (a pinch or a twisted sliver, as in GSHHG's
// intermediate Baltic coast): cuts out the shorter side. One cut per curve per round (a
// cut renumbers the curve's points). A loop of several curves may meet itself across the
// end of a curve (the binned GSHHG comes in pieces cut at its bins' edges): the sliver is
// cut out across the curves, at most once per loop per round (the cut changes the loop's
// curves).
bool cut_slivers(LoopRepair& r, const std::vector<const SegmentHit*>& stuck) {
  bool cut = false;
  std::vector<char> cut_curve(r.curves.size(), 0), cut_loop(r.loops.size(), 0);
  std::vector<std::uint32_t> left_loop;
  for (const SegmentHit* h : stuck) {
    if (h->loop_a != h->loop_b || r.loops[h->loop_a].dead) continue;
    const LoopVertexRef ra = r.refs[h->loop_a][h->seg_a], rb = r.refs[h->loop_b][h->seg_b];
    const geo::LonLat where = uv_to_lonlat(h->where);
    if (ra.curve != rb.curve) {
      WorkLoop& loop = r.loops[h->loop_a];
      if (cut_loop[h->loop_a] || cut_curve[ra.curve] || cut_curve[rb.curve]) continue;
      // The two segments' places on the loop, the earlier one first.
      const std::size_t sa = std::min(h->seg_a, h->seg_b), sb = std::max(h->seg_a, h->seg_b);
      const LoopVertexRef r1 = r.refs[h->loop_a][sa], r2 = r.refs[h->loop_a][sb];
      std::size_t i1 = loop.curves.size(), i2 = loop.curves.size();
      for (std::size_t k = 0; k < loop.curves.size(); ++k) {
        if (loop.curves[k] == r1.curve) i1 = k;
        if (loop.curves[k] == r2.curve) i2 = k;
      }
      const std::uint32_t a1 = r.curves[r1.curve].keep[r1.k], a2 = r.curves[r2.curve].keep[r2.k];
      if (cut_sliver_across(r.curves, loop, i1, a1, i2, a2, left_loop)) {
        const WorkCurve& c = r.curves[r1.curve];
        r.log.push_back({RepairKind::CutSliver, c.record, c.id, where, 0});
        cut = true;
        cut_loop[h->loop_a] = 1;
        r.changes.whole_loop(h->loop_a);
        for (std::uint32_t ci : {r1.curve, r2.curve}) cut_curve[ci] = 1;
        for (std::uint32_t ci : left_loop) cut_curve[ci] = 1;
        left_loop.clear();
      }
      continue;
    }
    if (cut_curve[ra.curve]) continue;
    WorkCurve& c = r.curves[ra.curve];
    if (cut_sliver(c, std::min(c.keep[ra.k], c.keep[rb.k]), std::max(c.keep[ra.k], c.keep[rb.k]))) {
      r.log.push_back({RepairKind::CutSliver, c.record, c.id, where, 0});
      cut = true;
      cut_curve[ra.curve] = 1;
      r.mark_loops_using(ra.curve);
    }
  }
  return cut;
}

// The error when the first stuck hit is on original data that no step could change.
CoastError unrepairable_error(const LoopRepair& r, const std::vector<const SegmentHit*>& stuck) {
  const SegmentHit& h = *stuck.front();
  const WorkCurve& ca = r.curves[r.refs[h.loop_a][h.seg_a].curve];
  const WorkCurve& cb = r.curves[r.refs[h.loop_b][h.seg_b].curve];
  const char* kind = h.kind == HitKind::Cross ? "cross" : h.kind == HitKind::Touch ? "touch" : "overlap";
  const std::string what =
      &ca == &cb || (ca.record == cb.record && ca.id == cb.id)
          ? fmt::format("the source shoreline (record {} id {}) meets itself ({}) and no sliver can be cut out",
                        ca.record, ca.id, kind)
          : fmt::format("the source shorelines (record {} id {} and record {} id {}) {} each other", ca.record,
                        ca.id, cb.record, cb.id, kind);
  return CoastError{"repair", static_cast<std::int64_t>(ca.record),
                    fmt::format("{}; {} such places cannot be repaired (a finer accuracy or a region avoiding "
                                "them may help)",
                                what, stuck.size()),
                    uv_to_lonlat(h.where)};
}

}  // namespace

void free_points(WorkCurve& c) {
  std::vector<geo::LonLat>().swap(c.full);
  std::vector<Vec2>().swap(c.uv);
  std::vector<double>().swap(c.gamma);
  std::vector<std::uint32_t>().swap(c.keep);
}

void loop_polygon(const std::vector<WorkCurve>& curves, const WorkLoop& loop, std::vector<Vec2>& uv,
                  std::vector<LoopVertexRef>* refs) {
  uv.clear();
  if (refs) refs->clear();
  for (std::uint32_t ci : loop.curves) {
    const WorkCurve& c = curves[ci];
    const std::size_t m = c.periodic ? c.keep.size() : c.keep.size() - 1;   // shared end point skipped
    for (std::uint32_t k = 0; k < m; ++k) {
      uv.push_back(c.uv[c.keep[k]]);
      if (refs) refs->push_back({ci, k});
    }
  }
}

Result<std::size_t> repair_loops(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops,
                                 const RepairOptions& opt, std::vector<RepairEntry>& log) {
  LoopRepair r(curves, loops, log);
  std::size_t round = 0;
  for (;; ++round) {
    r.rebuild_polygons();
    r.changes.active(curves, loops, r.refs, r.active);
    const std::vector<SegmentHit> hits = find_intersections_at(r.polys, r.active, resolve_thread_count(opt.threads));
    // Next round re-checks the segments met here (a hit left alone this round stays) and
    // those changed below.
    for (const SegmentHit& h : hits) {
      r.changes.touch_segment(curves, r.refs[h.loop_a], h.seg_a);
      r.changes.touch_segment(curves, r.refs[h.loop_b], h.seg_b);
    }
    if (hits.empty()) {
      if (!opt.check_splines || spline_pass(curves, loops, r.polys, r.refs, round, opt,
                                            static_cast<int>(round) < opt.max_rounds, log, r.changes))
        break;
      continue;   // points were put back: check the polygons again
    }
    if (static_cast<int>(round) >= opt.max_rounds)
      return CoastError{"repair", static_cast<std::int64_t>(curves[r.refs[hits[0].loop_a][0].curve].record),
                        fmt::format("{} intersections left after {} repair rounds", hits.size(), round),
                        uv_to_lonlat(hits[0].where)};
    std::vector<const SegmentHit*> stuck;
    if (put_back_original_points(r, hits, round, stuck)) continue;
    if (drop_small_islands(r, stuck, opt.radius)) continue;
    if (unite_overlapping_islands(r, stuck)) continue;
    if (cut_slivers(r, stuck)) continue;
    return unrepairable_error(r, stuck);
  }
  return round;
}

namespace {

// Joins island loop lb into la across the facing kept segments (la, ka) and (lb, kb):
// la's points from the end of its segment round to its start, then lb's likewise. lb is
// dead then and nothing reads its curve again: its points are freed (kept, the islands a
// continent took in held their points twice, to the end of the import).
//
// la's curve is made so in place, in ring order but not from its start: lb's run goes in
// after the start of la's segment, in place of the dropped originals of the segment (the
// points after it moved once), and the keep list is la's from ka + 1 round, then lb's. A
// continent takes in tens of islands across the straits' passes (Eurasia, 3 million
// source points at full resolution): turning its arrays to start at the segment's end at
// each merge copied all of them each time; the curve is turned once when the passes are
// done (start_at_first_kept). The arrays grow by an eighth
// beyond what a merge needs when they must grow (not by doubling: the full GSHHG's peak
// memory at 30 km), and handle_straits fits them to their size at its end.
void merge_across(std::vector<WorkCurve>& curves, WorkLoop& la, std::uint32_t ka, WorkLoop& lb, std::uint32_t kb) {
  WorkCurve& A = curves[la.curves[0]];
  WorkCurve& B = curves[lb.curves[0]];
  const std::size_t na = A.full.size(), nka = A.keep.size();
  const std::size_t end_a = A.keep[ka], from_a = A.keep[(ka + 1) % nka];
  const std::size_t nb = B.full.size(), nkb = B.keep.size();
  const std::size_t from_b = B.keep[(kb + 1) % nkb];
  // B's points from keep[kb+1] round to keep[kb] (inclusive): every retained point of B.
  const std::size_t len_b = (B.keep[kb] + nb - from_b) % nb + 1;
  // Where A's points go: those of its kept run stay in ring order; `at` is where B's run
  // starts. Without a wrap (from_a after end_a) the points from from_a on move by `shift`;
  // with one (the segment runs past A's last point to its first) the points before from_a
  // and after end_a are dropped and the run moved to the front.
  const bool wraps = from_a <= end_a;
  std::size_t at = 0;
  std::ptrdiff_t shift = 0;
  auto place = [&](auto& v) {
    using T = typename std::remove_reference_t<decltype(v)>::value_type;
    const std::size_t total = wraps ? end_a - from_a + 1 + len_b : na - (from_a - end_a - 1) + len_b;
    if (v.capacity() < total) v.reserve(total + total / 8);
    if (wraps) {
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(end_a + 1), v.end());
      v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(from_a));
      at = v.size();
      v.resize(total);
    } else {
      at = end_a + 1;
      shift = static_cast<std::ptrdiff_t>(at + len_b) - static_cast<std::ptrdiff_t>(from_a);
      if (shift > 0) {
        v.resize(total);
        std::move_backward(v.begin() + static_cast<std::ptrdiff_t>(from_a), v.begin() + static_cast<std::ptrdiff_t>(na),
                           v.end());
      } else if (shift < 0) {
        std::move(v.begin() + static_cast<std::ptrdiff_t>(from_a), v.end(),
                  v.begin() + static_cast<std::ptrdiff_t>(at + len_b));
        v.resize(total);
      }
    }
    return std::span<T>(v).subspan(at, len_b);
  };
  {
    const std::span<geo::LonLat> full = place(A.full);
    const std::span<Vec2> uv = place(A.uv);
    const std::span<double> gamma = place(A.gamma);
    for (std::size_t s = 0, i = from_b; s < len_b; ++s, i = i + 1 == nb ? 0 : i + 1) {
      full[s] = B.full[i];
      uv[s] = B.uv[i];
      gamma[s] = B.gamma[i];
    }
  }
  std::rotate(A.keep.begin(), A.keep.begin() + static_cast<std::ptrdiff_t>((ka + 1) % nka), A.keep.end());
  for (std::uint32_t& k : A.keep)
    k = static_cast<std::uint32_t>(wraps ? k - from_a : (k >= from_a ? static_cast<std::ptrdiff_t>(k) + shift : k));
  if (A.keep.capacity() < nka + nkb) A.keep.reserve(nka + nkb + (nka + nkb) / 8);
  for (std::size_t j = 0; j < nkb; ++j)
    A.keep.push_back(static_cast<std::uint32_t>(at + (B.keep[(kb + 1 + j) % nkb] + nb - from_b) % nb));
  A.periodic = true;
  free_points(B);
  lb.dead = true;
}

// A curve merge_across left starting elsewhere turned to start at its first kept point:
// the points in the order the merges' runs give them, as the rest of the import has them.
void start_at_first_kept(WorkCurve& c) {
  const std::size_t s = c.keep.empty() ? 0 : c.keep[0];
  if (s == 0) return;
  const auto by = static_cast<std::ptrdiff_t>(s);
  std::rotate(c.full.begin(), c.full.begin() + by, c.full.end());
  std::rotate(c.uv.begin(), c.uv.begin() + by, c.uv.end());
  std::rotate(c.gamma.begin(), c.gamma.begin() + by, c.gamma.end());
  const std::size_t n = c.full.size();
  for (std::uint32_t& k : c.keep) k = static_cast<std::uint32_t>((k + n - s) % n);
}

// A loop the pass before merged into another (j): its polygon and widths are the two
// loops' (unchanged since they were made) turned and put end to end as merge_across put the
// points (LoopJoin), the same values in the same order; its vertex refs those of its one
// curve (ci) in order. Made again from the curve they were a gather through the keep list
// of a continent's source points and a division per vertex, for every merge.
void join_polygons(std::vector<std::vector<Vec2>>& polys, std::vector<std::vector<double>>& width,
                   std::vector<std::vector<LoopVertexRef>>& refs, const LoopJoin& j, std::uint32_t ci) {
  std::vector<Vec2> p;
  std::vector<double> wd;
  p.reserve(std::size_t{j.n_into} + j.n_from);
  wd.reserve(p.capacity());
  for (const auto [l, k, n] : {std::array{j.into, j.k_into, j.n_into}, std::array{j.from, j.k_from, j.n_from}}) {
    const auto at = static_cast<std::ptrdiff_t>((k + 1) % n);
    p.insert(p.end(), polys[l].begin() + at, polys[l].end());
    p.insert(p.end(), polys[l].begin(), polys[l].begin() + at);
    wd.insert(wd.end(), width[l].begin() + at, width[l].end());
    wd.insert(wd.end(), width[l].begin(), width[l].begin() + at);
  }
  polys[j.into] = std::move(p);
  width[j.into] = std::move(wd);
  refs[j.into].resize(polys[j.into].size());
  for (std::uint32_t k = 0; k < refs[j.into].size(); ++k) refs[j.into][k] = {ci, k};
  std::vector<Vec2>().swap(polys[j.from]);
  std::vector<double>().swap(width[j.from]);
  std::vector<LoopVertexRef>().swap(refs[j.from]);
}

double lambda(Vec2 uv, double radius) { return 2.0 * radius / (1.0 + norm2(uv)); }

// The narrowest place per pair of loops of the near misses `near` (sorted by place), in
// the order the pairs first appear; a place where the two segments face each other
// (facing(m)) is preferred to one where they do not. best_of: one slot per loop, all
// empty (~0) on entry and on return.
template <class Facing>
void best_per_loop_pair(const std::vector<NearMiss>& near, Facing&& facing, std::vector<std::size_t>& best_of,
                        std::vector<NearMiss>& best, std::vector<char>& best_facing) {
  // The entry of each pair of loops in `best` (a search through `best` for each near miss
  // was near misses x pairs: thousands of each at full resolution). `near` is sorted by
  // place (find_near_misses, find_near_misses_again), so a loop's records as loop_a are
  // consecutive: the entry of (loop_a, loop_b) is best_of[loop_b] while loop_a's run
  // lasts, the slots it filled emptied when it ends (a hash map of the pairs was 290,000
  // look-ups a pass at 3 km, most of the passes' own time).
  constexpr std::size_t kNoEntry = ~std::size_t{0};
  std::uint32_t run_a = 0;
  std::size_t run_first = 0;   // the first entry of `best` made in loop run_a's run
  for (const NearMiss& m : near) {
    const bool f = facing(m);
    if (m.loop_a != run_a) {
      for (std::size_t e = run_first; e < best.size(); ++e) best_of[best[e].loop_b] = kNoEntry;
      run_a = m.loop_a;
      run_first = best.size();
    }
    SM_ASSERT(m.loop_a >= run_a, "handle_straits: near misses not sorted by loop (repair.cpp, handle_straits)");
    const bool fresh = best_of[m.loop_b] == kNoEntry;
    if (fresh) best_of[m.loop_b] = best.size();
    const std::size_t i = best_of[m.loop_b];
    if (fresh) {
      best.push_back(m);
      best_facing.push_back(f);
    } else if ((f && !best_facing[i]) || (f == static_cast<bool>(best_facing[i]) && m.distance < best[i].distance)) {
      best[i] = m;
      best_facing[i] = f;
    }
  }
  for (std::size_t e = run_first; e < best.size(); ++e) best_of[best[e].loop_b] = kNoEntry;
}


}  // namespace

void handle_straits(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops, const RepairOptions& opt,
                    std::vector<RepairEntry>& log) {
  if (!(opt.strait_factor > 0)) return;
  // Each pass merges every island at most once (its polygon changes); chains of islands
  // across several straits take several passes.
  constexpr int kMaxPasses = 16;
  // A pass changes only the loops it merges (one made of two, the other dead): the next
  // pass makes the polygons and widths of those again and keeps the others'. Its near
  // misses are the pass before's, renumbered through the merges, with only the segments
  // at the bridges searched again (renumber_for_joins, find_near_misses_again): a full
  // search of the world each pass was most of the straits' time (16 passes at 3 km), and
  // searching every segment of a merged continent again was half of that.
  std::vector<std::vector<Vec2>> polys(loops.size());
  std::vector<std::vector<LoopVertexRef>> refs(loops.size());
  std::vector<std::vector<double>> width(loops.size());
  std::vector<char> changed(loops.size(), 1);
  std::vector<NearMiss> near;
  std::vector<LoopJoin> joins;   // the pass before's merges
  std::vector<char> joined(loops.size(), 0);
  std::vector<char> took_in(loops.size(), 0);   // the loops merge_across joined another into
  BridgeCheck bridges(loops.size());   // the bridges checked against the pass's polygons
  std::vector<std::size_t> best_of(loops.size(), ~std::size_t{0});   // per loop: best_per_loop_pair's slots
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    // A loop the pass before merged into another: its polygon and widths from the two
    // loops' (join_polygons).
    for (const LoopJoin& j : joins) {
      bridges.merged(j, polys);
      join_polygons(polys, width, refs, j, loops[j.into].curves[0]);
      joined[j.into] = joined[j.from] = 1;
    }
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (!changed[l] || joined[l]) continue;
      polys[l].clear();
      refs[l].clear();
      width[l].clear();
      if (loops[l].dead) continue;
      loop_polygon(curves, loops[l], polys[l], &refs[l]);
      for (std::size_t s = 0; s < polys[l].size(); ++s) {
        const LoopVertexRef r = refs[l][s];
        const WorkCurve& c = curves[r.curve];
        width[l].push_back(opt.strait_factor * c.gamma[c.keep[r.k]] / lambda(polys[l][s], opt.radius));
      }
    }
    if (pass == 0) {
      near = find_near_misses(polys, width);
    } else {
      std::vector<std::vector<char>> active(loops.size());
      for (std::size_t l = 0; l < loops.size(); ++l)
        if (changed[l]) active[l].assign(polys[l].size(), 0);
      for (const LoopJoin& j : joins)
        SM_ASSERT(polys[j.into].size() == std::size_t{j.n_into} + j.n_from && polys[j.from].empty(),
                  "handle_straits: a merged loop's polygon is not its two loops' (repair.cpp, handle_straits)");
      renumber_for_joins(joins, near, active);
      for (std::size_t l = 0; l < loops.size(); ++l)
        if (active[l].size() != polys[l].size()) active[l].assign(polys[l].size(), 0);
      near = find_near_misses_again(polys, width, active, std::move(near), resolve_thread_count(opt.threads));
    }
    std::fill(changed.begin(), changed.end(), 0);
    for (const LoopJoin& j : joins) joined[j.into] = joined[j.from] = 0;
    joins.clear();
    bridges.new_pass();
    // Narrowest place per pair of loops, narrowest pairs first; a place where the two
    // segments face each other (run in opposite directions, more than 120 degrees apart)
    // is preferred, since only there can a bridge close the strait.
    auto facing = [&](const NearMiss& m) {
      const auto& pa = polys[m.loop_a];
      const auto& pb = polys[m.loop_b];
      const Vec2 da = pa[(m.seg_a + 1) % pa.size()] - pa[m.seg_a];
      const Vec2 db = pb[(m.seg_b + 1) % pb.size()] - pb[m.seg_b];
      return dot(da, db) < -0.5 * norm(da) * norm(db);
    };
    std::vector<NearMiss> best;
    std::vector<char> best_facing;
    best_per_loop_pair(near, facing, best_of, best, best_facing);
    std::vector<std::size_t> order(best.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return best[a].distance < best[b].distance; });
    bool merged = false;
    std::vector<RepairEntry> pending;
    for (std::size_t oi : order) {
      const NearMiss& m = best[oi];
      const LoopVertexRef ra = refs[m.loop_a][m.seg_a], rb = refs[m.loop_b][m.seg_b];
      const WorkCurve& ca = curves[ra.curve];
      const double metres = m.distance * lambda(m.where, opt.radius);
      WorkLoop& la = loops[m.loop_a];
      WorkLoop& lb = loops[m.loop_b];
      const bool can_merge = opt.close_straits && best_facing[oi] && m.loop_a != m.loop_b && la.hole && lb.hole &&
                             la.curves.size() == 1 && lb.curves.size() == 1 && !changed[m.loop_a] &&
                             !changed[m.loop_b] && curves[la.curves[0]].periodic && curves[lb.curves[0]].periodic;
      if (can_merge) {
        // The merge adds only the two bridge edges a[k]->b[k+1] and b[k]->a[k+1]; the
        // loops were intersection-free, so checking those two edges is enough.
        const std::vector<Vec2>& pa = polys[m.loop_a];
        const std::vector<Vec2>& pb = polys[m.loop_b];
        const Vec2 a0 = pa[m.seg_a], a1 = pa[(m.seg_a + 1) % pa.size()];
        const Vec2 b0 = pb[m.seg_b], b1 = pb[(m.seg_b + 1) % pb.size()];
        const std::array<std::array<Vec2, 2>, 2> bridge{{{a0, b1}, {b0, a1}}};
        bool bad = segments_meet(bridge[0][0], bridge[0][1], bridge[1][0], bridge[1][1]);
        // Against the segments of the loops not merged away in this pass, near the bridge.
        for (const auto& br : bridge) bad = bad || bridges.crosses(loops, polys, br[0], br[1]);
        if (!bad) {
          joins.push_back({m.loop_a, m.loop_b, ra.k, rb.k, static_cast<std::uint32_t>(pa.size()),
                           static_cast<std::uint32_t>(pb.size())});
          merge_across(curves, la, ra.k, lb, rb.k);
          took_in[m.loop_a] = 1;
          changed[m.loop_a] = changed[m.loop_b] = 1;   // merged once this pass, made again the next
          merged = true;
          log.push_back({RepairKind::MergedIslands, ca.record, ca.id, uv_to_lonlat(m.where), metres});
          continue;
        }
      }
      pending.push_back({RepairKind::NarrowStrait, ca.record, ca.id, uv_to_lonlat(m.where), metres});
    }
    if (!merged || pass + 1 == kMaxPasses) {   // straits left open: reported once, from the final pass
      log.insert(log.end(), pending.begin(), pending.end());
      break;
    }
  }
  for (std::size_t l = 0; l < loops.size(); ++l)
    if (took_in[l] && !loops[l].dead) start_at_first_kept(curves[loops[l].curves[0]]);
  // The merged curves' arrays, grown with room to spare (merge_across), fitted to their
  // size before the passages' pool is made beside them.
  for (const WorkLoop& l : loops)
    if (!l.dead && l.curves.size() == 1) {
      WorkCurve& c = curves[l.curves[0]];
      if (c.full.capacity() > c.full.size()) {
        c.full.shrink_to_fit();
        c.uv.shrink_to_fit();
        c.gamma.shrink_to_fit();
        c.keep.shrink_to_fit();
      }
    }
}

}  // namespace sm::coast
