// Import pipeline: filter -> clean -> orient -> clip -> coarsen -> (u,v) topology ->
// repair -> model. Orientation convention: water on the left of every loop.
#include "coast/import.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "base/cpu_clock.h"
#include "base/elapsed.h"
#include "base/parallel.h"
#include "base/release_memory.h"
#include "coast/coastline_option_id.h"
#include "coast/deviation.h"
#include "coast/passages.h"
#include "coast/region_polygon.h"
#include "exact/ring.h"
#include "coast/repair.h"

namespace sm::coast {

std::size_t ImportReport::count(RepairKind k) const {
  std::size_t n = 0;
  for (const auto& e : repair) n += e.kind == k;
  return n;
}

namespace {

// The pipeline steps numbered in build_coast_model: the units of its progress stage.
constexpr std::uint64_t kImportSteps = 8;
constexpr double kImportGravity = 9.81;   // m/s^2, as mesh/time_step.h

const char* describe(RepairKind k) {
  switch (k) {
    case RepairKind::Refined: return "original points put back on a crossing segment";
    case RepairKind::DroppedIsland: return "island below the accuracy touching another coastline dropped";
    case RepairKind::UnitedIslands: return "islands overlapping in the source united";
    case RepairKind::CutSliver: return "self-touching sliver of the source shoreline cut out";
    case RepairKind::MergedIslands: return "islands merged across a strait narrower than the accuracy";
    case RepairKind::NarrowStrait: return "strait narrower than the accuracy kept open";
    case RepairKind::OutsideWater: return "island outside every water surface dropped";
    case RepairKind::SplineHull: return "original points put back where the B-splines crossed or touched";
    case RepairKind::SplineMayCross: return "the B-splines cross or touch here on the source data";
    case RepairKind::ClosedPassage:
      return "passage narrower than MinChannelWidth or Mesh.MinTimeStep needs closed by two dams";
    case RepairKind::NarrowWater: return "water narrower than MinChannelWidth behind a dam removed";
    case RepairKind::DamPlaced: return "dam placed across the water";
    case RepairKind::KeptOpen: return "passage kept open by KeepOpen";
    case RepairKind::DroppedSea: return "sea holding no SeaAt point dropped";
    case RepairKind::GrazingCrossing:
      return "Region polygon edge crossing water for less than the accuracy: coast joined across it";
    case RepairKind::PocketLeftOut: return "water inside the Region polygon only across such crossings left out";
  }
  return "?";
}

bool is_passage_kind(RepairKind k) {
  return k == RepairKind::ClosedPassage || k == RepairKind::NarrowWater || k == RepairKind::DamPlaced;
}

// The figure each kind of change is told with ("" when its place says it all).
std::string figure_of(const RepairEntry& e) {
  switch (e.kind) {
    case RepairKind::NarrowStrait:
    case RepairKind::MergedIslands:
    case RepairKind::ClosedPassage:
    case RepairKind::KeptOpen:
      // With Mesh.MinTimeStep: the Courant step one element across it would have set.
      return std::isnan(e.step) ? fmt::format("width {:.0f} m", e.value)
                                : fmt::format("width {:.1f} m, time step {:.2f} s{}", e.value, e.step,
                                              e.step_unmet ? ", under Mesh.MinTimeStep" : "");
    case RepairKind::DroppedSea: return fmt::format("{:.0f} km^2", e.value);
    case RepairKind::PocketLeftOut: return fmt::format("{:.3g} km^2", e.value);
    case RepairKind::NarrowWater: return fmt::format("mean width {:.0f} m", e.value);
    case RepairKind::DamPlaced:
    case RepairKind::GrazingCrossing: return fmt::format("{:.0f} m long", e.value);
    case RepairKind::Refined:
    case RepairKind::SplineHull: return fmt::format("{} point{}", e.value, e.value == 1 ? "" : "s");
    default: return {};
  }
}

// Each step's options as the import holds them, with the context every step shares (the
// sphere's radius, the threads, gamma) taken from the import: set once, in ImportOptions.
CoarsenOptions in_context(CoarsenOptions o, const ImportOptions& opt) {
  o.gamma = opt.gamma;
  o.radius = opt.radius;
  o.threads = opt.threads;
  return o;
}
DeviationOptions in_context(DeviationOptions o, const ImportOptions& opt) {
  o.radius = opt.radius;
  o.threads = opt.threads;
  return o;
}
RepairOptions in_context(RepairOptions o, const ImportOptions& opt) {
  o.radius = opt.radius;
  o.threads = opt.threads;
  return o;
}
PassageOptions in_context(PassageOptions o, const ImportOptions& opt) {
  o.radius = opt.radius;
  o.threads = opt.threads;
  o.width_at = nullptr;   // the import's own, from min_time_step
  return o;
}

// A Region polygon's edge that grazes the shore crosses a cove or a bay's mouth for a few
// tens of metres: an open boundary that short, between two coasts, would be a sliver. Each
// open piece shorter than gamma at its middle is dropped and the coast pieces on either
// side are joined along it (the coarsening then thins the join like any coast). Water the
// polygon takes in only across such crossings (the head of a loch its edge cuts) is left
// out: the region's seas are those its open boundaries reach.
void skip_grazing_crossings(RegionResult& r, const ImportOptions& opt, std::vector<RepairEntry>& log) {
  std::vector<char> left_out(r.loops.size(), 0);
  for (std::size_t li = 0; li < r.loops.size(); ++li) {
    RegionLoop& loop = r.loops[li];
    const std::size_t n = loop.pieces.size();
    if (n < 2) continue;
    std::vector<Vec3> mid;
    std::vector<double> len;
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < n; ++i) {
      const RegionPiece& p = loop.pieces[i];
      if (!p.open_boundary) continue;
      double l = 0;
      for (std::size_t k = 0; k + 1 < p.pts.size(); ++k)
        l += norm(geo::sphere_from_lonlat(p.pts[k + 1], opt.radius) - geo::sphere_from_lonlat(p.pts[k], opt.radius));
      open.push_back(i);
      len.push_back(l);
      mid.push_back(geo::sphere_from_lonlat(p.pts[p.pts.size() / 2], opt.radius));
    }
    if (open.empty()) continue;
    std::vector<double> gamma(mid.size());
    opt.gamma(mid, gamma);
    std::vector<char> skip(n, 0);
    std::size_t skipped = 0;
    for (std::size_t k = 0; k < open.size(); ++k)
      if (len[k] < gamma[k]) {
        skip[open[k]] = 1;
        ++skipped;
        const RegionPiece& p = loop.pieces[open[k]];
        log.push_back({RepairKind::GrazingCrossing, static_cast<std::size_t>(-1), -1, p.pts[p.pts.size() / 2], len[k]});
      }
    if (skipped == 0) continue;
    // Start at a coast piece that no skipped piece leads into (one is: some open piece is kept).
    if (skipped == open.size()) {
      std::vector<geo::LonLat> ring;
      for (const RegionPiece& p : loop.pieces) ring.insert(ring.end(), p.pts.begin(), p.pts.end() - 1);
      log.push_back({RepairKind::PocketLeftOut, static_cast<std::size_t>(-1), -1, ring.front(),
                     std::abs(ring_area_km2(ring, opt.radius * 1e-3))});
      left_out[li] = 1;
      continue;
    }
    std::size_t s = 0;
    while (s < n && (loop.pieces[s].open_boundary || skip[(s + n - 1) % n])) ++s;
    std::vector<RegionPiece> out;
    bool joining = false;
    for (std::size_t k = 0; k < n; ++k) {
      RegionPiece& p = loop.pieces[(s + k) % n];
      if (skip[(s + k) % n] || joining) {   // appended to the piece before, its first point shared
        out.back().pts.insert(out.back().pts.end(), p.pts.begin() + 1, p.pts.end());
        joining = skip[(s + k) % n] != 0;
        continue;
      }
      out.push_back(std::move(p));
    }
    loop.pieces = std::move(out);
  }
  std::size_t kept = 0;
  for (std::size_t li = 0; li < r.loops.size(); ++li)
    if (!left_out[li]) {
      if (kept != li) r.loops[kept] = std::move(r.loops[li]);   // no self-move: it would empty the loop
      ++kept;
    }
  r.loops.resize(kept);
}

}  // namespace

std::vector<ReportLine> ImportReport::items() const {
  std::vector<ReportLine> out;
  if (!clean.entries.empty()) out.push_back({"cleaning: " + clean.summary(), {}, {}, false, {}, false});
  std::size_t few = 0, small = 0;
  for (const auto& d : dropped) (d.reason == DropReason::TooFewPoints ? few : small)++;
  if (few + small > 0)
    out.push_back({fmt::format("coarsening: {} rings too small for the accuracy and {} below MinArea dropped", few,
                               small),
                   {}, {}, false, {}, false});
  for (const auto& e : repair) {
    ReportLine l;
    l.what = describe(e.kind);
    l.figure = figure_of(e);
    l.has_place = true;
    // Rings keep contiguous longitudes (Eurasia runs to 190E); places are told in (-180, 180].
    l.where = e.where;
    l.where.lon = std::remainder(l.where.lon, 360.0);
    if (l.where.lon <= -180) l.where.lon += 360;
    l.passage = is_passage_kind(e.kind);
    l.sea_dropped = e.kind == RepairKind::DroppedSea;
    l.kept_open = e.kind == RepairKind::KeptOpen;
    l.step_unmet = e.step_unmet;
    if (e.kind == RepairKind::ClosedPassage || e.kind == RepairKind::DroppedSea) l.rank = e.value;
    // Changes of no source record (the Region's own pieces) say only their place.
    const std::string source =
        e.record == static_cast<std::size_t>(-1) ? std::string() : fmt::format("record {} (id {}) ", e.record, e.id);
    l.text = fmt::format("{}at lon {:.5f} lat {:.5f}: {}{}", source, l.where.lon, l.where.lat, l.what,
                         l.figure.empty() ? std::string() : " (" + l.figure + ")");
    l.entry = e;
    l.entry->where = l.where;
    out.push_back(std::move(l));
  }
  return out;
}

namespace {

bool is_water_level(int level) { return level == 2 || level == 4; }

// The curve of a coarse ring, its (u,v) points not yet made (set_uv, on the threads) but
// their array reserved here, on the calling thread: the heap's layout is the serial
// import's (made on a worker, the 160 MB of them at 3 km came from another arena and
// raised the -nt 2 peak by 15 MB).
WorkCurve make_curve(CoarseRing&& cr, bool open_boundary) {
  WorkCurve w;
  w.full = std::move(cr.ring.pts);
  w.gamma = std::move(cr.gamma);
  w.keep = std::move(cr.keep);
  w.periodic = cr.ring.closed;
  w.open_boundary = open_boundary;
  w.record = cr.ring.record;
  w.id = cr.ring.id;
  w.uv.reserve(w.full.size());
  return w;
}

// Every curve's (u,v) points from its lon/lat ones: each curve's are its own (one point's
// image depends on that point alone), so the chunks of curves go to the threads and the
// result is the same bytes for every count. On one thread this was the curves step's
// whole time (0.3 s of CPU for the 10 million source points of the full GSHHG).
void set_uv(std::vector<WorkCurve>& curves, const geo::PolarSphere& ps, int threads) {
  constexpr std::size_t kChunk = 8;   // curves: the continents lead, so small chunks share them out
  parallel_for_chunks(resolve_thread_count(threads), curves.size(), kChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      WorkCurve& c = curves[i];
      for (const geo::LonLat p : c.full) c.uv.push_back(ps.param_from_lonlat(p));   // within its reserve
    }
  });
}

// Every point on one line (exact): a loop without area.
bool all_collinear(const std::vector<Vec2>& p) {
  std::size_t j = 1;
  while (j < p.size() && p[j] == p[0]) ++j;
  if (j == p.size()) return true;
  for (std::size_t i = j + 1; i < p.size(); ++i)
    if (orient2d(p[0], p[j], p[i]) != Sign::Zero) return false;
  return true;
}

// A B-spline cuts a corner of its control polygon by about a quarter of the spacing
// there: after coarsening (points >= gamma apart), a box piece keeps each corner and, on
// either side, the farthest of region.cpp's graded samples within gamma / 10 of it. The
// spline then turns the corner within gamma / 10 (its hull near the corner is that thin)
// and follows the parallels and meridians elsewhere, the control points lying on them.
void keep_box_corners(CoarseRing& cr, const std::vector<std::size_t>& corners, double radius) {
  if (corners.empty()) return;
  const std::vector<geo::LonLat>& pts = cr.ring.pts;
  const std::size_t n = pts.size();
  std::vector<std::uint32_t>& keep = cr.keep;
  for (std::size_t c : corners) {
    if (c >= n) continue;
    const double limit = 0.1 * cr.gamma[c];
    keep.push_back(static_cast<std::uint32_t>(c));
    for (int dir : {-1, 1}) {
      // Walk away from the corner along the ring (wrapping when closed) while within limit.
      std::size_t best = c;
      for (std::size_t step = 1; step < n; ++step) {
        const std::size_t i = dir > 0 ? c + step : c - step;
        std::size_t at = i;
        if (dir > 0 && i >= n) {
          if (!cr.ring.closed) break;
          at = i - n;
        } else if (dir < 0 && step > c) {
          if (!cr.ring.closed) break;
          at = n + c - step;
        }
        if (chord(pts[c], pts[at], radius) > limit) break;
        best = at;
      }
      if (best != c) keep.push_back(static_cast<std::uint32_t>(best));
    }
  }
  std::sort(keep.begin(), keep.end());
  keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
}

void reverse_curve(WorkCurve& c) {
  const auto n = static_cast<std::uint32_t>(c.full.size());
  std::reverse(c.full.begin(), c.full.end());
  std::reverse(c.uv.begin(), c.uv.end());
  std::reverse(c.gamma.begin(), c.gamma.end());
  for (auto& k : c.keep) k = n - 1 - k;
  std::reverse(c.keep.begin(), c.keep.end());
}

// Which seas (outer loop o with holes_of[o]) hold one of the points: a point must lie in
// the water of one of them (strictly inside the smallest outer loop round it and outside
// its holes); one on land is an error naming the land ring it is in.
Result<std::vector<char>> seas_at(const std::vector<geo::LonLat>& points, const std::vector<std::vector<Vec2>>& polys,
                                  const std::vector<std::uint32_t>& outers,
                                  const std::vector<std::vector<std::uint32_t>>& holes_of,
                                  const std::vector<Ring>& land_rings, const std::vector<WorkCurve>& curves,
                                  const std::vector<WorkLoop>& loops) {
  const geo::PolarSphere ps({0, 0, 0}, 1.0);
  std::vector<char> kept(outers.size(), 0);
  auto area = [&](std::uint32_t l) {
    double a = 0;
    const auto& p = polys[l];
    for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
    return std::abs(a);
  };
  for (const geo::LonLat pt : points) {
    const Vec2 uv = ps.param_from_lonlat(pt);
    std::size_t best = outers.size();
    for (std::size_t o = 0; o < outers.size(); ++o)
      if (point_in_ring(polys[outers[o]], uv) && (best == outers.size() || area(outers[o]) < area(outers[best])))
        best = o;
    std::optional<std::uint32_t> hole;
    if (best < outers.size())
      for (std::uint32_t h : holes_of[best])
        if (point_in_ring(polys[h], uv)) hole = h;
    if (best < outers.size() && !hole) {
      kept[best] = 1;
      continue;
    }
    std::string which;
    if (hole) {
      const WorkCurve& c = curves[loops[*hole].curves[0]];
      which = fmt::format("island record {} (id {})", c.record, c.id);
    } else {
      for (const Ring& r : land_rings) {
        std::vector<Vec2> xy;
        for (int k = -1; k <= 1 && which.empty(); ++k) {
          xy.clear();
          for (auto p : r.pts) xy.push_back({p.lon + 360.0 * k, p.lat});
          if (point_in_ring(xy, {pt.lon, pt.lat})) which = fmt::format("land ring record {} (id {})", r.record, r.id);
        }
        if (!which.empty()) break;
      }
      if (which.empty()) which = "no sea (it is on land or outside the water the import kept)";
    }
    CoastError e{"", -1, fmt::format("the SeaAt point (lon {:.6f}, lat {:.6f}) lies in {}", pt.lon, pt.lat, which), pt};
    e.option = coast_option_string(CoastOpt::SeaAt);
    return e;
  }
  return kept;
}

// A point of the sea with outer loop `outer` and holes `holes`: just left of (inside) the
// middle of one of its outer loop's longest segments, the first found outside every hole.
Vec2 point_inside(const std::vector<std::vector<Vec2>>& polys, std::uint32_t outer,
                  const std::vector<std::uint32_t>& holes) {
  const auto& p = polys[outer];
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) order[i] = i;
  auto len = [&](std::size_t i) { return norm(p[(i + 1) % p.size()] - p[i]); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return len(a) > len(b); });
  for (std::size_t k = 0; k < std::min<std::size_t>(order.size(), 64); ++k) {
    const Vec2 a = p[order[k]], b = p[(order[k] + 1) % p.size()], d = b - a;
    const Vec2 x = 0.5 * (a + b) + 1e-3 * Vec2{-d.y, d.x};
    bool ok = point_in_ring(p, x);
    for (std::uint32_t h : holes) ok = ok && !point_in_ring(polys[h], x);
    if (ok) return x;
  }
  return p.empty() ? Vec2{0, 0} : p[0];
}

// The area in km^2 of a sea on the sphere of `radius` (metres): its loops' signed (u,v)
// areas (outer counter-clockwise, holes clockwise) as triangle fans, each triangle scaled
// by the PolarSphere's area factor at its centroid.
double sea_area_km2(const std::vector<std::vector<Vec2>>& polys, std::uint32_t outer,
                    const std::vector<std::uint32_t>& holes, double radius) {
  double a = 0;
  auto add = [&](const std::vector<Vec2>& p) {
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      const Vec2 c = (1.0 / 3.0) * (p[0] + p[i] + p[i + 1]);
      const double lambda = 2.0 * radius / (1.0 + norm2(c));
      a += 0.5 * cross(p[i] - p[0], p[i + 1] - p[0]) * lambda * lambda;
    }
  };
  add(polys[outer]);
  for (std::uint32_t h : holes) add(polys[h]);
  return std::abs(a) * 1e-6;
}

// The import's state between its stages (build_coast_model below), each stage one of the
// numbered steps of coast/import.h's account.
struct ImportWork {
  Coastline data;
  const ImportOptions& opt;
  CoastModel model;
  ImportReport& rep = model.report;
  const geo::PolarSphere ps{{0, 0, 0}, 1.0};
  std::uint64_t steps_done = 0;

  std::vector<Ring> rings;
  std::vector<Ring> land_rings;   // in lon/lat, to name the one a SeaAt point falls in
  std::optional<LonLatBox> box;
  std::vector<Ring> to_coarsen;                 // closed islands first, then loop pieces
  std::vector<std::pair<std::size_t, std::size_t>> piece_span;   // per region loop: [first, last) in to_coarsen
  std::vector<char> piece_is_boundary;
  std::vector<std::vector<std::size_t>> piece_corners;       // per region piece: box corners in its pts
  bool region_empty = false;
  CoarsenResult whole;    // the closed rings coarsened
  CoarsenResult pieces;   // the region loops' pieces coarsened
  std::vector<WorkCurve> curves;
  std::vector<WorkLoop> loops;
  RepairOptions ro;
  // Surfaces: the loops' polygons, the outer loops (largest first), the holes of each.
  std::vector<std::vector<Vec2>> polys;
  std::vector<std::uint32_t> outers;
  std::vector<std::vector<std::uint32_t>> holes_of;
  std::vector<std::uint32_t> unassigned;

  ImportWork(Coastline d, const ImportOptions& o) : data(std::move(d)), opt(o) {}
  ImportWork(const ImportWork&) = delete;
  ImportWork& operator=(const ImportWork&) = delete;
  double cpu_mark = process_cpu_seconds();
  std::chrono::steady_clock::time_point wall_mark = std::chrono::steady_clock::now();

  void step_done() { progress_update(opt.progress, ++steps_done); }
  // The CPU seconds since the last charge go to step `name` of the report's account.
  void charge(std::string_view name) {
    const double now = process_cpu_seconds();
    auto it = std::find_if(rep.step_cpu.begin(), rep.step_cpu.end(),
                           [name](const ImportStepTime& t) { return t.name == name; });
    if (it == rep.step_cpu.end()) it = rep.step_cpu.insert(it, ImportStepTime{std::string(name), 0});
    it->seconds += now - cpu_mark;
    it->wall += seconds_since(wall_mark);
    cpu_mark = now;
    wall_mark = std::chrono::steady_clock::now();
  }
  // An error of a stage that names no file: the shoreline file's.
  CoastError in_file(CoastError e) const {
    e.file = data.file;
    return e;
  }
};

// 1. Levels: the rings of the levels asked for.
void keep_levels(ImportWork& w) {
  const ImportOptions& opt = w.opt;
  for (Ring& r : w.data.rings) {
    const bool want = std::find(opt.levels.begin(), opt.levels.end(), r.level) != opt.levels.end() ||
                      (opt.antarctica_level != 0 && r.level == opt.antarctica_level);
    if (want) w.rings.push_back(std::move(r));
  }
  // The levels left out (lakes when only land is asked for) are not read again: their
  // points would otherwise stay allocated through the whole import.
  std::vector<Ring>().swap(w.data.rings);
}

// 2. Cleaning and orientation; the patch, when given, replaces the data inside its box.
std::optional<CoastError> clean_and_orient(ImportWork& w) {
  const ImportOptions& opt = w.opt;
  {
    Coastline c;
    c.rings = std::move(w.rings);
    w.rep.clean = clean(c, opt.threads);
    merge_touching_rings(c, w.rep.clean, opt.threads);
    w.rings = std::move(c.rings);
  }
  w.rep.reversed = orient_rings(w.rings);
  if (opt.patch_box) {   // the local source replaces the data inside its box
    Coastline c;
    c.rings = opt.patch;
    clean(c, opt.threads);   // the same cleaning as the data's (its report is not merged)
    orient_rings(c.rings);
    PatchReport pr;
    auto spliced = splice_patch(w.rings, c.rings, *opt.patch_box, opt.radius, &pr);
    if (!spliced) return spliced.error();
    w.rings = std::move(*spliced);
    w.rep.patch = pr;
  }
  if (!opt.sea_at.empty())
    for (const Ring& r : w.rings)
      if (r.closed && !r.wraps_pole && !is_water_level(r.level)) w.land_rings.push_back(r);
  return std::nullopt;
}

// 3. Region clipping: which rings stay whole, which loops are made of pieces.
std::optional<CoastError> clip_region(ImportWork& w) {
  const ImportOptions& opt = w.opt;
  std::vector<Ring>& rings = w.rings;
  w.box = opt.region;
  const bool has_open = std::any_of(rings.begin(), rings.end(), [](const Ring& r) { return !r.closed; });
  if (!w.box && has_open) {
    if (opt.use_file_region && w.data.region)
      w.box = w.data.region;
    else
      return CoastError{w.data.file, -1, "the file holds open (cut) coastlines: a Region is needed to close them", {}};
  }
  if (w.box) {
    Result<RegionResult> clipped = RegionResult{};
    if (opt.region_polygon.empty()) {
      clipped = clip_to_region(rings, *w.box, opt.region_options);
    } else {
      auto poly = RegionPolygon::make(opt.region_polygon);
      if (!poly) return poly.error();
      clipped = clip_to_polygon(rings, *poly, opt.region_options);
      if (clipped) skip_grazing_crossings(*clipped, opt, w.rep.repair);
    }
    if (!clipped) return clipped.error();
    // Moved: only the pieces' record, id and level are read from `rings` below.
    for (std::size_t i : clipped->inside) w.to_coarsen.push_back(std::move(rings[i]));
    w.piece_is_boundary.assign(w.to_coarsen.size(), 0);
    for (const RegionLoop& loop : clipped->loops) {
      const std::size_t first = w.to_coarsen.size();
      for (const RegionPiece& p : loop.pieces) {
        Ring r;
        r.pts = p.pts;
        r.closed = loop.pieces.size() == 1;   // the box alone: one closed boundary curve
        if (p.open_boundary) {
          r.record = static_cast<std::size_t>(-1);
          r.id = -1;
        } else {
          r.record = rings[p.ring].record;
          r.id = rings[p.ring].id;
          r.level = rings[p.ring].level;
        }
        w.to_coarsen.push_back(std::move(r));
        w.piece_is_boundary.push_back(p.open_boundary ? 1 : 0);
        w.piece_corners.push_back(p.corners);
      }
      w.piece_span.push_back({first, w.to_coarsen.size()});
    }
  } else {
    w.to_coarsen = std::move(rings);
    w.piece_is_boundary.assign(w.to_coarsen.size(), 0);
  }
  std::vector<Ring>().swap(rings);
  // A Region holding no shoreline: its box is the only loop, all open boundary.
  w.region_empty = w.box && std::all_of(w.piece_is_boundary.begin(), w.piece_is_boundary.end(),
                                        [](char b) { return b != 0; });
  return std::nullopt;
}

// 4. Coarsening (a closed region box that is a single curve may not be dropped).
std::optional<CoastError> coarsen_rings(ImportWork& w) {
  const ImportOptions& opt = w.opt;
  const CoarsenOptions co = in_context(opt.coarsen, opt);
  const std::size_t n_whole = w.piece_span.empty() ? w.to_coarsen.size() : w.piece_span.front().first;
  std::vector<Ring> whole(std::make_move_iterator(w.to_coarsen.begin()),
                          std::make_move_iterator(w.to_coarsen.begin() + static_cast<long>(n_whole)));
  std::vector<Ring> pieces(std::make_move_iterator(w.to_coarsen.begin() + static_cast<long>(n_whole)),
                           std::make_move_iterator(w.to_coarsen.end()));
  std::vector<Ring>().swap(w.to_coarsen);   // the rings moved out, their shells left
  auto cw = coarsen(std::move(whole), co);
  if (!cw) return cw.error();
  CoarsenOptions cp = co;
  cp.min_area_km2 = 0;
  cp.min_points = 3;
  auto cpieces = coarsen(std::move(pieces), cp);
  if (!cpieces) return cpieces.error();
  if (!cpieces->dropped.empty())   // only the box alone, as one closed curve, can be dropped
    return CoastError{w.data.file, -1, "the region box is smaller than the accuracy", {}};
  for (std::size_t k = 0; k < cpieces->rings.size(); ++k)
    keep_box_corners(cpieces->rings[k], w.piece_corners[k], opt.radius);
  w.rep.dropped = std::move(cw->dropped);
  w.rep.points_in = cw->points_in + cpieces->points_in;
  w.whole = std::move(*cw);
  w.pieces = std::move(*cpieces);
  return std::nullopt;
}

// 5. Work curves and loops; orientation in (u,v) with water on the left. Loops the
// coarsening left without area (a corner of the region cut off by a coast piece, below the
// accuracy) are dropped.
void make_work_loops(ImportWork& w) {
  std::vector<WorkCurve>& curves = w.curves;
  std::vector<WorkLoop>& loops = w.loops;
  for (CoarseRing& cr : w.whole.rings) {
    const int level = cr.ring.level;
    const bool pole = cr.ring.wraps_pole;
    curves.push_back(make_curve(std::move(cr), false));
    WorkLoop loop;
    loop.curves = {static_cast<std::uint32_t>(curves.size() - 1)};
    // Land rings are holes in the water; the ring round the singular point (the South
    // Pole) and lakes are outer boundaries of water.
    const bool south_pole_ring = pole && curves.back().full.front().lat < 0;
    loop.hole = !(south_pole_ring || is_water_level(level));
    loops.push_back(std::move(loop));
  }
  std::size_t at = 0;
  for (const auto& span : w.piece_span) {
    WorkLoop loop;
    loop.hole = false;
    for (std::size_t k = span.first; k < span.second; ++k, ++at) {
      curves.push_back(make_curve(std::move(w.pieces.rings[at]), w.piece_is_boundary[k] != 0));
      loop.curves.push_back(static_cast<std::uint32_t>(curves.size() - 1));
    }
    loops.push_back(std::move(loop));
  }
  // The coarse rings' points are the curves' now: their shells go.
  std::vector<CoarseRing>().swap(w.whole.rings);
  std::vector<CoarseRing>().swap(w.pieces.rings);
  set_uv(curves, w.ps, w.opt.threads);
  std::vector<Vec2> poly;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    WorkLoop& loop = loops[l];
    loop_polygon(curves, loop, poly, nullptr);
    if (poly.size() < 3 || all_collinear(poly)) {
      const WorkCurve& c = curves[loop.curves[0]];
      loop.dead = true;
      w.rep.repair.push_back({RepairKind::DroppedIsland, c.record, c.id, c.full.front(), 0});
    }
  }
}

// One repair pass over the loops, its rounds counted; errors name the shoreline file.
std::optional<CoastError> repair_pass(ImportWork& w) {
  auto rounds = repair_loops(w.curves, w.loops, w.ro, w.rep.repair);
  if (!rounds) return w.in_file(rounds.error());
  w.rep.repair_rounds += *rounds;
  return std::nullopt;
}

// 6. Repair, the straits, and the orientation once the loops are simple (the
// extreme-vertex test needs a simple polygon): water on the left, outer loops
// counter-clockwise, holes clockwise.
std::optional<CoastError> repair_and_orient(ImportWork& w) {
  w.ro = in_context(w.opt.repair, w.opt);
  if (auto e = repair_pass(w)) return e;
  w.charge("repair");
  const std::size_t merged_before = w.rep.count(RepairKind::MergedIslands);
  // The first pass's rounds (polygons, grids, segment lists) and then the straits' passes
  // (their polygons, widths and near misses) leave their freed heap resident under the
  // next step's arrays, which come from elsewhere in the heap: at 3 km on the full GSHHG
  // the straits ended 500 MB resident for 300 in use, and the second repair pass peaked
  // on top of that (docs/kernel.md, "Memory"). Giving it back costs a few milliseconds.
  release_free_memory();
  // The box alone has no strait: near its corners its own sides came out as one.
  if (!w.region_empty) handle_straits(w.curves, w.loops, w.ro, w.rep.repair);
  release_free_memory();
  w.charge("straits");
  // A merge across a strait adds two bridge edges, checked against the polygons only: the
  // curves through them are checked again.
  if (w.ro.check_splines && w.rep.count(RepairKind::MergedIslands) > merged_before)
    if (auto e = repair_pass(w)) return e;
  w.charge("repair");
  std::vector<Vec2> poly;
  for (std::size_t l = 0; l < w.loops.size(); ++l) {
    WorkLoop& loop = w.loops[l];
    if (loop.dead) continue;
    loop_polygon(w.curves, loop, poly, nullptr);
    const Sign o = ring_orientation(poly);
    if ((o == Sign::Positive) != !loop.hole) {
      if (loop.curves.size() != 1)
        return CoastError{w.data.file, -1, "a region loop runs the wrong way round (land data not land-on-left)",
                          w.curves[loop.curves[0]].full.front()};
      reverse_curve(w.curves[loop.curves[0]]);
    }
  }
  return std::nullopt;
}

// The points of the curves no live loop uses (islands dropped, united or merged into
// another loop: merge_across frees those it merges away itself) are freed before the
// passages' pool is made beside the rest: on the full GSHHG at 3 km, a million source
// points (40 bytes each) under the import's peak.
void free_unused_curves(ImportWork& w) {
  std::vector<char> used(w.curves.size(), 0);
  for (const WorkLoop& l : w.loops)
    if (!l.dead)
      for (std::uint32_t ci : l.curves) used[ci] = 1;
  for (std::size_t ci = 0; ci < w.curves.size(); ++ci)
    if (!used[ci]) free_points(w.curves[ci]);
}

// Passages and dams, on the simple loops oriented water on the left; the dams are checked
// against the curves like any coast, and the loops they make are oriented by construction.
std::optional<CoastError> close_narrow_passages(ImportWork& w) {
  const ImportOptions& opt = w.opt;
  std::vector<WorkCurve>& curves = w.curves;
  const bool by_step = opt.min_time_step > 0 && opt.depth_at;
  if (!(opt.passages.min_width > 0 || by_step || !opt.passages.dams.empty() || !opt.passages.keep_open.empty()))
    return std::nullopt;
  PassageOptions po = in_context(opt.passages, opt);
  if (by_step) {
    // One element across a passage of width w at depth H gives the step w / sqrt(g H):
    // narrower than dt sqrt(g H) it is closed. The search radius is the widest such
    // width at the coast's points (a passage lies between two of them).
    const double dt = opt.min_time_step;
    const auto& depth_at = opt.depth_at;
    auto width_at = [dt, depth_at](geo::LonLat ll) {
      return dt * std::sqrt(kImportGravity * std::max(0.0, depth_at(ll)));
    };
    for (const WorkLoop& l : w.loops)
      if (!l.dead)
        for (std::uint32_t ci : l.curves)
          for (std::uint32_t j : curves[ci].keep) po.min_width = std::max(po.min_width, width_at(curves[ci].full[j]));
    const double floor = opt.passages.min_width;
    po.width_at = [width_at, floor](geo::LonLat ll) { return std::max(floor, width_at(ll)); };
  }
  auto closed = close_passages(curves, w.loops, po, w.rep.repair);
  w.charge("passages");
  if (!closed) {
    CoastError e = closed.error();
    e.option = e.file;
    return w.in_file(std::move(e));
  }
  if (*closed && w.ro.check_splines)
    if (auto e = repair_pass(w)) return e;
  w.charge("repair");
  // The straits were measured on the coarsened curves; the passages changed them: a cut
  // refused at a pinch puts the source points back (a 31 m gap between two 2 km
  // segments is a 110 m strait in the source), and a closure makes land of a strait.
  // They are measured again on the curves as they now are, without new merges (a strait
  // the passages kept open stays open).
  if (*closed && !w.region_empty) {
    std::erase_if(w.rep.repair, [](const RepairEntry& e) { return e.kind == RepairKind::NarrowStrait; });
    RepairOptions again = w.ro;
    again.close_straits = false;
    handle_straits(curves, w.loops, again, w.rep.repair);
  }
  w.charge("straits");
  // The step each closure saved, each strait left open and each KeepOpen passage costs,
  // at its place's depth.
  if (by_step)
    for (RepairEntry& e : w.rep.repair) {
      if (e.kind != RepairKind::ClosedPassage && e.kind != RepairKind::KeptOpen &&
          e.kind != RepairKind::NarrowStrait && e.kind != RepairKind::MergedIslands)
        continue;
      const double h = opt.depth_at(e.where);
      if (!(h > 0)) continue;
      e.step = e.value / std::sqrt(kImportGravity * h);
      e.step_unmet = e.kind == RepairKind::KeptOpen && e.step < opt.min_time_step;
    }
  return std::nullopt;
}

// 7. Surfaces: each hole goes to the smallest outer loop that contains it; the ocean
// first: the loop round the South Pole or, in a region, the largest loop.
// The loops' polygons, the outers' areas and each hole's outer are found on the threads,
// each written to its own slot (a hole's outer depends on the polygons alone), and then
// taken in loop order: the same surfaces for every thread count.
void assign_holes(ImportWork& w) {
  const std::vector<WorkLoop>& loops = w.loops;
  const int threads = resolve_thread_count(w.opt.threads);
  constexpr std::size_t kChunk = 64;   // loops
  w.polys.resize(loops.size());
  // Each polygon's array is reserved here, on the calling thread (as for the curves' (u,v)
  // points in set_uv), and filled on the threads within it.
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (loops[l].dead) continue;
    std::size_t n = 0;
    for (std::uint32_t ci : loops[l].curves) {
      const WorkCurve& c = w.curves[ci];
      if (!c.keep.empty()) n += c.periodic ? c.keep.size() : c.keep.size() - 1;
    }
    w.polys[l].reserve(n);
  }
  parallel_for_chunks(threads, loops.size(), kChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t l = b; l < e; ++l)
      if (!loops[l].dead) loop_polygon(w.curves, loops[l], w.polys[l], nullptr);
  });
  for (std::uint32_t l = 0; l < loops.size(); ++l)
    if (!loops[l].dead && !loops[l].hole) w.outers.push_back(l);
  // Each outer's (doubled) area once: it was summed again at every comparison below.
  std::vector<double> area_of(loops.size(), 0.0);
  parallel_for_chunks(threads, w.outers.size(), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t o = b; o < e; ++o) {
      double a = 0;
      const auto& p = w.polys[w.outers[o]];
      for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
      area_of[w.outers[o]] = std::abs(a);
    }
  });
  auto area = [&](std::uint32_t l) { return area_of[l]; };
  std::vector<std::uint32_t>& outers = w.outers;
  std::stable_sort(outers.begin(), outers.end(), [&](std::uint32_t a, std::uint32_t b) { return area(a) > area(b); });
  w.holes_of.resize(outers.size());
  // Per hole: the index in `outers` of the smallest outer loop round its first point.
  std::vector<std::size_t> best_of(loops.size(), outers.size());
  parallel_for_chunks(threads, loops.size(), kChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t l = b; l < e; ++l) {
      if (loops[l].dead || !loops[l].hole) continue;
      std::size_t best = outers.size();
      for (std::size_t o = 0; o < outers.size(); ++o)
        if (point_in_ring(w.polys[outers[o]], w.polys[l][0]) &&
            (best == outers.size() || area(outers[o]) < area(outers[best])))
          best = o;
      best_of[l] = best;
    }
  });
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    if (loops[l].dead || !loops[l].hole) continue;
    const std::size_t best = best_of[l];
    if (best < outers.size()) {
      w.holes_of[best].push_back(l);
    } else if (outers.empty()) {
      w.unassigned.push_back(l);
    } else {
      const WorkCurve& c = w.curves[loops[l].curves[0]];
      w.rep.repair.push_back({RepairKind::OutsideWater, c.record, c.id, c.full[c.keep[0]], 0});
    }
  }
}

// SeaAt: only the seas holding one of its points are kept, the others reported dropped.
std::optional<CoastError> keep_seas(ImportWork& w) {
  const ImportOptions& opt = w.opt;
  if (opt.sea_at.empty()) return std::nullopt;
  auto kept = seas_at(opt.sea_at, w.polys, w.outers, w.holes_of, w.land_rings, w.curves, w.loops);
  if (!kept) return w.in_file(kept.error());
  std::vector<std::uint32_t> outers_kept;
  std::vector<std::vector<std::uint32_t>> holes_kept;
  for (std::size_t o = 0; o < w.outers.size(); ++o) {
    if ((*kept)[o]) {
      outers_kept.push_back(w.outers[o]);
      holes_kept.push_back(std::move(w.holes_of[o]));
      continue;
    }
    ++w.model.seas_dropped;
    const WorkCurve& c = w.curves[w.loops[w.outers[o]].curves[0]];
    w.rep.repair.push_back({RepairKind::DroppedSea, c.record, c.id,
                            w.ps.lonlat_from_param(point_inside(w.polys, w.outers[o], w.holes_of[o])),
                            sea_area_km2(w.polys, w.outers[o], w.holes_of[o], opt.radius)});
  }
  w.outers = std::move(outers_kept);
  w.holes_of = std::move(holes_kept);
  w.unassigned.clear();
  return std::nullopt;
}

// One loop into the model (its curves' kept points); returns its index.
std::uint32_t emit_loop(ImportWork& w, std::uint32_t l) {
  CoastModel& model = w.model;
  CoastLoop out;
  for (std::uint32_t ci : w.loops[l].curves) {
    const WorkCurve& c = w.curves[ci];
    CoastCurve cc;
    cc.periodic = c.periodic;
    cc.open_boundary = c.open_boundary;
    cc.record = c.record;
    cc.id = c.id;
    for (std::uint32_t k : c.keep) {
      cc.ll.push_back(c.full[k]);
      cc.uv.push_back(c.uv[k]);
    }
    w.rep.points_out += cc.ll.size();
    out.curves.push_back(static_cast<std::uint32_t>(model.curves.size()));
    model.curves.push_back(std::move(cc));
  }
  model.loops.push_back(std::move(out));
  return static_cast<std::uint32_t>(model.loops.size() - 1);
}

// 8. Output, loops numbered surface by surface (outer first, then its holes).
void emit_model(ImportWork& w) {
  for (std::size_t o = 0; o < w.outers.size(); ++o) {
    CoastSurface s;
    s.outer = emit_loop(w, w.outers[o]);
    for (std::uint32_t h : w.holes_of[o]) s.holes.push_back(emit_loop(w, h));
    w.model.surfaces.push_back(std::move(s));
  }
  for (std::uint32_t l : w.unassigned) w.model.unassigned.push_back(emit_loop(w, l));
}

}  // namespace

Result<CoastModel> build_coast_model(Coastline data, const ImportOptions& opt) {
  ImportWork w(std::move(data), opt);
  // The stage ends on every return, errors included.
  struct StageEnd {
    Progress* p;
    ~StageEnd() { progress_end(p); }
  } stage_end{opt.progress};
  progress_begin(opt.progress, "coastline", kImportSteps);
  keep_levels(w);
  w.charge("levels");
  w.step_done();
  if (auto e = clean_and_orient(w)) return *e;
  w.charge("clean");
  w.step_done();
  if (auto e = clip_region(w)) return *e;
  w.charge("clip");
  w.step_done();
  if (auto e = coarsen_rings(w)) return *e;
  w.charge("coarsen");
  w.step_done();
  make_work_loops(w);
  w.charge("curves");
  w.step_done();
  // The curves back within the bound of their source points (before the repair, which
  // then sees the curves as they will be drawn).
  w.rep.deviation = bound_deviation(w.curves, in_context(opt.deviation, opt));
  // Its per-curve arrays (many from the heap) are freed: their pages are given back, or
  // they stay resident under the repair's and the passages' arrays (the import's peak).
  release_free_memory();
  w.charge("deviation");
  if (auto e = repair_and_orient(w)) return *e;
  free_unused_curves(w);
  // The same for the repair rounds' polygons and grids, before the passages' pool is made.
  release_free_memory();
  w.charge("orient");
  if (auto e = close_narrow_passages(w)) return *e;
  w.step_done();
  assign_holes(w);
  if (auto e = keep_seas(w)) return *e;
  w.charge("surfaces");
  w.step_done();
  emit_model(w);
  w.charge("model");
  w.step_done();
  w.model.region_empty = w.region_empty;
  return std::move(w.model);
}

}  // namespace sm::coast
