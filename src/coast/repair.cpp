// Repair by local refinement toward the original shoreline, then by dropping islands
// below the accuracy; strait detection and island merging across straits.
#include "coast/repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "coast/intersections.h"
#include "mesh/predicates.h"

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

// Segment s of a loop polygon starts at refs[s]; which curve/keep position owns it.
LoopVertexRef segment_owner(const std::vector<LoopVertexRef>& refs, std::size_t s) { return refs[s]; }

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

double mean_gamma(const WorkCurve& c) {
  double g = 0;
  for (double x : c.gamma) g += x;
  return c.gamma.empty() ? 0 : g / static_cast<double>(c.gamma.size());
}

}  // namespace

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
  std::vector<std::vector<Vec2>> polys(loops.size());
  std::vector<std::vector<LoopVertexRef>> refs(loops.size());
  auto rebuild = [&] {
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (loops[l].dead) {
        polys[l].clear();
        refs[l].clear();
      } else {
        loop_polygon(curves, loops[l], polys[l], &refs[l]);
      }
    }
  };
  std::size_t round = 0;
  for (;; ++round) {
    rebuild();
    const std::vector<SegmentHit> hits = find_intersections(polys);
    if (hits.empty()) break;
    if (static_cast<int>(round) >= opt.max_rounds)
      return CoastError{"repair", static_cast<std::int64_t>(curves[refs[hits[0].loop_a][0].curve].record),
                        fmt::format("{} intersections left after {} repair rounds", hits.size(), round),
                        uv_to_lonlat(hits[0].where)};
    // 1. Put original points back on every offending segment that has some.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> inserts;   // (curve, full index)
    std::vector<const SegmentHit*> stuck;
    std::vector<std::uint32_t> idx;
    for (const SegmentHit& h : hits) {
      bool any = false;
      for (const auto& [l, s] : {std::pair{h.loop_a, h.seg_a}, std::pair{h.loop_b, h.seg_b}}) {
        const LoopVertexRef r = segment_owner(refs[l], s);
        refine_indices(curves[r.curve], r.k, round, idx);
        for (std::uint32_t i : idx) inserts.push_back({r.curve, i});
        any |= !idx.empty();
      }
      if (!any) stuck.push_back(&h);
    }
    if (!inserts.empty()) {
      std::sort(inserts.begin(), inserts.end());
      inserts.erase(std::unique(inserts.begin(), inserts.end()), inserts.end());
      for (std::size_t i = 0; i < inserts.size();) {
        const std::uint32_t ci = inserts[i].first;
        WorkCurve& c = curves[ci];
        std::size_t j = i;
        while (j < inserts.size() && inserts[j].first == ci) c.keep.push_back(inserts[j++].second);
        std::sort(c.keep.begin(), c.keep.end());
        c.keep.erase(std::unique(c.keep.begin(), c.keep.end()), c.keep.end());
        log.push_back({RepairKind::Refined, c.record, c.id, c.full[inserts[i].second], static_cast<double>(j - i)});
        i = j;
      }
      continue;
    }
    // 2. Original data still meets: drop an island below the accuracy, else fail.
    bool dropped = false;
    for (const SegmentHit* h : stuck) {
      for (std::uint32_t l : {h->loop_a, h->loop_b}) {
        WorkLoop& loop = loops[l];
        if (loop.dead || !loop.hole || loop.curves.size() != 1) continue;
        const WorkCurve& c = curves[loop.curves[0]];
        if (!c.periodic || island_perimeter_m(c, opt.radius) >= 5.0 * mean_gamma(c)) continue;
        loop.dead = true;
        dropped = true;
        log.push_back({RepairKind::DroppedIsland, c.record, c.id, uv_to_lonlat(h->where), 0});
        break;
      }
    }
    if (dropped) continue;
    // 3. A loop that meets itself on original data (a pinch or a twisted sliver, as in
    //    GSHHG's intermediate Baltic coast): cut out the shorter side.
    // One cut per curve per round (a cut renumbers the curve's points).
    bool cut = false;
    std::vector<char> cut_curve(curves.size(), 0);
    for (const SegmentHit* h : stuck) {
      if (h->loop_a != h->loop_b || loops[h->loop_a].dead) continue;
      const LoopVertexRef ra = refs[h->loop_a][h->seg_a], rb = refs[h->loop_b][h->seg_b];
      if (ra.curve != rb.curve || cut_curve[ra.curve]) continue;
      WorkCurve& c = curves[ra.curve];
      const geo::LonLat where = uv_to_lonlat(h->where);
      if (cut_sliver(c, std::min(c.keep[ra.k], c.keep[rb.k]), std::max(c.keep[ra.k], c.keep[rb.k]))) {
        log.push_back({RepairKind::CutSliver, c.record, c.id, where, 0});
        cut = true;
        cut_curve[ra.curve] = 1;
      }
    }
    if (cut) continue;
    const SegmentHit& h = *stuck.front();
    const WorkCurve& ca = curves[refs[h.loop_a][h.seg_a].curve];
    const WorkCurve& cb = curves[refs[h.loop_b][h.seg_b].curve];
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
  return round;
}

namespace {

// Joins island loop lb into la across the facing kept segments (la, ka) and (lb, kb):
// la's points from the end of its segment round to its start, then lb's likewise.
void merge_across(std::vector<WorkCurve>& curves, WorkLoop& la, std::uint32_t ka, WorkLoop& lb, std::uint32_t kb) {
  WorkCurve& A = curves[la.curves[0]];
  const WorkCurve& B = curves[lb.curves[0]];
  WorkCurve M;
  M.periodic = true;
  M.record = A.record;
  M.id = A.id;
  auto append = [&M](const WorkCurve& c, std::uint32_t k) {
    // From keep[k+1] round to keep[k] (inclusive), keeping the retained flags.
    const std::size_t n = c.full.size();
    const std::size_t from = c.keep[(k + 1) % c.keep.size()];
    const std::size_t to = c.keep[k];
    const std::size_t len = (to + n - from) % n + 1;
    std::vector<char> kept(n, 0);
    for (auto i : c.keep) kept[i] = 1;
    for (std::size_t s = 0; s < len; ++s) {
      const std::size_t i = (from + s) % n;
      if (kept[i]) M.keep.push_back(static_cast<std::uint32_t>(M.full.size()));
      M.full.push_back(c.full[i]);
      M.uv.push_back(c.uv[i]);
      M.gamma.push_back(c.gamma[i]);
    }
  };
  append(A, ka);
  append(B, kb);
  A = std::move(M);
  lb.dead = true;
}

double lambda(Vec2 uv, double radius) { return 2.0 * radius / (1.0 + norm2(uv)); }

// Closed segments pq and rs share a point (exact predicates).
bool segments_meet(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  const Sign o1 = orient2d(p, q, r), o2 = orient2d(p, q, s), o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  if (o1 == Sign::Zero && o2 == Sign::Zero) {
    auto within = [](Vec2 a, Vec2 b, Vec2 c) {
      return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
             c.y <= std::max(a.y, b.y);
    };
    return within(p, q, r) || within(p, q, s) || within(r, s, p) || within(r, s, q);
  }
  return !(o1 != Sign::Zero && o1 == o2) && !(o3 != Sign::Zero && o3 == o4);
}

}  // namespace

void handle_straits(std::vector<WorkCurve>& curves, std::vector<WorkLoop>& loops, const RepairOptions& opt,
                    std::vector<RepairEntry>& log) {
  if (!(opt.strait_factor > 0)) return;
  // Each pass merges every island at most once (its polygon changes); chains of islands
  // across several straits take several passes.
  constexpr int kMaxPasses = 16;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    std::vector<std::vector<Vec2>> polys(loops.size());
    std::vector<std::vector<LoopVertexRef>> refs(loops.size());
    std::vector<std::vector<double>> width(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (loops[l].dead) continue;
      loop_polygon(curves, loops[l], polys[l], &refs[l]);
      for (std::size_t s = 0; s < polys[l].size(); ++s) {
        const LoopVertexRef r = refs[l][s];
        const WorkCurve& c = curves[r.curve];
        width[l].push_back(opt.strait_factor * c.gamma[c.keep[r.k]] / lambda(polys[l][s], opt.radius));
      }
    }
    const std::vector<NearMiss> near = find_near_misses(polys, width);
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
    for (const NearMiss& m : near) {
      const bool f = facing(m);
      std::size_t i = 0;
      while (i < best.size() && !(best[i].loop_a == m.loop_a && best[i].loop_b == m.loop_b)) ++i;
      if (i == best.size()) {
        best.push_back(m);
        best_facing.push_back(f);
      } else if ((f && !best_facing[i]) || (f == static_cast<bool>(best_facing[i]) && m.distance < best[i].distance)) {
        best[i] = m;
        best_facing[i] = f;
      }
    }
    std::vector<std::size_t> order(best.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return best[a].distance < best[b].distance; });
    bool merged = false;
    std::vector<char> touched(loops.size(), 0);
    std::vector<RepairEntry> pending;
    for (std::size_t oi : order) {
      const NearMiss& m = best[oi];
      const LoopVertexRef ra = refs[m.loop_a][m.seg_a], rb = refs[m.loop_b][m.seg_b];
      const WorkCurve& ca = curves[ra.curve];
      const double metres = m.distance * lambda(m.where, opt.radius);
      WorkLoop& la = loops[m.loop_a];
      WorkLoop& lb = loops[m.loop_b];
      const bool can_merge = opt.close_straits && best_facing[oi] && m.loop_a != m.loop_b && la.hole && lb.hole &&
                             la.curves.size() == 1 && lb.curves.size() == 1 && !touched[m.loop_a] &&
                             !touched[m.loop_b] && curves[la.curves[0]].periodic && curves[lb.curves[0]].periodic;
      if (can_merge) {
        // The merge adds only the two bridge edges a[k]->b[k+1] and b[k]->a[k+1]; the
        // loops were intersection-free, so checking those two edges is enough.
        const std::vector<Vec2>& pa = polys[m.loop_a];
        const std::vector<Vec2>& pb = polys[m.loop_b];
        const Vec2 a0 = pa[m.seg_a], a1 = pa[(m.seg_a + 1) % pa.size()];
        const Vec2 b0 = pb[m.seg_b], b1 = pb[(m.seg_b + 1) % pb.size()];
        const std::array<std::array<Vec2, 2>, 2> bridges{{{a0, b1}, {b0, a1}}};
        bool bad = segments_meet(bridges[0][0], bridges[0][1], bridges[1][0], bridges[1][1]);
        for (std::size_t l = 0; l < polys.size() && !bad; ++l) {
          if (loops[l].dead) continue;
          const auto& p = polys[l];
          for (std::size_t i = 0; i < p.size() && !bad; ++i) {
            const Vec2 s0 = p[i], s1 = p[(i + 1) % p.size()];
            for (const auto& br : bridges) {
              if (std::max(s0.x, s1.x) < std::min(br[0].x, br[1].x) || std::min(s0.x, s1.x) > std::max(br[0].x, br[1].x) ||
                  std::max(s0.y, s1.y) < std::min(br[0].y, br[1].y) || std::min(s0.y, s1.y) > std::max(br[0].y, br[1].y))
                continue;
              // Edges sharing an end point with the bridge are its neighbours in the new loop.
              if (s0 == br[0] || s0 == br[1] || s1 == br[0] || s1 == br[1]) continue;
              if (segments_meet(br[0], br[1], s0, s1)) {
                bad = true;
                break;
              }
            }
          }
        }
        if (!bad) {
          merge_across(curves, la, ra.k, lb, rb.k);
          touched[m.loop_a] = touched[m.loop_b] = 1;
          merged = true;
          log.push_back({RepairKind::MergedIslands, ca.record, ca.id, uv_to_lonlat(m.where), metres});
          continue;
        }
      }
      pending.push_back({RepairKind::NarrowStrait, ca.record, ca.id, uv_to_lonlat(m.where), metres});
    }
    if (!merged || pass + 1 == kMaxPasses) {   // straits left open: reported once, from the final pass
      log.insert(log.end(), pending.begin(), pending.end());
      return;
    }
  }
}

}  // namespace sm::coast
