// Writes the GSHHG crude world ocean as a plain Gmsh script, the kind people write by hand
// or with Plugin(GSHHS): an Earth-sized PolarSphere (Gmsh's convention, docs/geometry.md
// section 1: (u,v) unit-scaled, the North Pole at (0,0), the South Pole at infinity), one
// Point per GSHHG crude shoreline point of the land rings (level 1) and Antarctica's ice
// front (level 5), read from the system's binned_GSHHS_c.nc (Debian gmt-gshhg-low,
// .ci/deps), then either a Line between consecutive points (`lines`) or one closed BSpline
// per ring (`bsplines`), a Curve Loop per ring, one Plane Surface with the continents and
// islands as holes, and a constant MathEval size field.
//
// The outer loop: on the chart the South Pole is at infinity, so the ring that holds it on
// the sphere (Antarctica) encloses every other ring, and Gmsh wants it first in the Plane
// Surface. It is found from the chart, not from the data's wraps_pole flag: the ring of
// largest (u,v) area, then checked to hold a point of every other ring (else an error).
// The points are written as GSHHG gives them but for two kinds of degenerate place, where
// the script would be invalid (the reader already keeps a repeated consecutive point once,
// and the closing point of each ring is its first point's tag):
// - zero-width spikes P -> Q -> P (GMT's joining of bin pieces at lon 0 leaves two in the
//   crude world, near 0E 49.33N and 0E 53.6N, the second P -> Q -> P -> Q): Q and the second
//   P are dropped. As Lines the loop retraces a segment; gmsh -2 stops on the second
//   ("Unable to recover the edge ... on curve 3616"), stereomesh on the first (a located
//   curves-intersect error, "distinct nodes at the same place").
// - bsplines only: a ring whose B-spline crosses another ring's or its own
//   (coast/spline_check.h; of a pair, the smaller ring) is left out: 12 small islands of 3
//   to 8 points cut across the coast beside them. For the sliver off west Greenland (3
//   points, two of them 40 m apart) sampling Gmsh's own evaluation of the two curves finds
//   the crossings; Gmsh meshes such a file only because its 2-node mesh of the sliver
//   misses them, stereomesh stops with a located curves-intersect error.
// --raw writes every point and ring (the invalid script, to see those errors).
//
// Usage: bench_crude_world_geo lines|bsplines SIZE_M OUT.geo [--raw] [BINNED_FILE]
// Both stereomesh -2 and gmsh -2 mesh OUT.geo (tests/tools/check_crude_world.sh, the
// figures in docs/coastlines.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "coast/read_gshhg_binned.h"
#include "coast/spline_check.h"
#include "exact/ring.h"
#include "geo/sphere.h"

namespace {

double ring_area(const std::vector<sm::Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) a += p[j].x * p[i].y - p[i].x * p[j].y;
  return 0.5 * a;
}

bool same_place(sm::geo::LonLat a, sm::geo::LonLat b) {
  const double dlon = std::fmod(std::fabs(a.lon - b.lon), 360.0);
  return a.lat == b.lat && (dlon == 0 || std::fabs(a.lat) == 90);
}

// Drops zero-width spikes P -> Q -> P of a ring (cyclic): Q and the second P go. Each pass
// removes two points or stops, so the loop is bounded by the ring's size.
std::size_t drop_spikes(std::vector<sm::Vec2>& r) {
  std::size_t dropped = 0;
  for (bool again = true; again && r.size() > 3;) {
    again = false;
    for (std::size_t i = 0; i < r.size() && r.size() > 3; ++i) {
      const std::size_t n = r.size(), a = (i + n - 1) % n, b = (i + 1) % n;
      if (r[a].x == r[b].x && r[a].y == r[b].y) {
        // Remove i and b (b may wrap to 0: erase the larger index first).
        const std::size_t hi = std::max(i, b), lo = std::min(i, b);
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(hi));
        r.erase(r.begin() + static_cast<std::ptrdiff_t>(lo));
        dropped += 2;
        again = true;
        break;
      }
    }
  }
  return dropped;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4 || (std::strcmp(argv[1], "lines") != 0 && std::strcmp(argv[1], "bsplines") != 0)) {
    std::fprintf(stderr, "usage: bench_crude_world_geo lines|bsplines SIZE_M OUT.geo [--raw] [BINNED_FILE]\n");
    return 2;
  }
  int arg = 4;
  const bool raw = argc > arg && std::strcmp(argv[arg], "--raw") == 0;
  if (raw) ++arg;
  const bool lines = std::strcmp(argv[1], "lines") == 0;
  const double size = std::atof(argv[2]);
  if (!(size > 0)) return std::fprintf(stderr, "bench_crude_world_geo: SIZE_M must be positive\n"), 2;
  const std::string path = argc > arg ? std::string(argv[arg]) : sm::coast::gshhg_binned_file('c');
  sm::coast::GshhgBinnedOptions opt;   // levels {1} and Antarctica's ice front (5): the world ocean's coast
  auto coast = sm::coast::read_gshhg_binned(path, opt);
  if (!coast) return std::fprintf(stderr, "%s\n", coast.error().to_string().c_str()), 1;

  const double radius = sm::geo::kEarthRadius;
  const sm::geo::PolarSphere unit({0, 0, 0}, 1.0);   // unit-scaled (u,v), as Plugin(GSHHS) writes them
  std::vector<std::vector<sm::Vec2>> rings;
  for (const sm::coast::Ring& r : coast->rings) {
    std::size_t n = r.pts.size();
    if (n > 1 && same_place(r.pts.front(), r.pts.back())) --n;   // closed on the first point's tag
    if (n < 3) continue;
    std::vector<sm::Vec2>& uv = rings.emplace_back();
    for (std::size_t i = 0; i < n; ++i) uv.push_back(unit.param_from_lonlat(r.pts[i]));
  }
  std::size_t spike_points = 0, crossing_rings = 0;
  if (!raw)
    for (std::vector<sm::Vec2>& r : rings) spike_points += drop_spikes(r);
  std::size_t outer = 0;   // before any ring is left out: the crossing check keeps it
  for (std::size_t k = 1; k < rings.size(); ++k)
    if (std::fabs(ring_area(rings[k])) > std::fabs(ring_area(rings[outer]))) outer = k;
  if (!raw && !lines) {
    std::vector<sm::coast::SplineLoop> loops(rings.size());
    for (std::size_t k = 0; k < rings.size(); ++k) loops[k].pts = rings[k];
    std::vector<bool> drop(rings.size(), false);
    for (const sm::coast::HullOverlap& c : sm::coast::find_spline_crossings(loops)) {
      // A ring whose spline crosses itself goes; of two, the smaller; never the outer ring.
      std::uint32_t small = rings[c.loop_a].size() <= rings[c.loop_b].size() ? c.loop_a : c.loop_b;
      if (small == outer) small = small == c.loop_a ? c.loop_b : c.loop_a;
      if (small == outer) {
        std::fprintf(stderr, "bench_crude_world_geo: the B-spline of the outer ring crosses itself\n");
        return 1;
      }
      if (!drop[small]) ++crossing_rings;
      drop[small] = true;
    }
    std::vector<std::vector<sm::Vec2>> kept;
    std::size_t kept_outer = 0;
    for (std::size_t k = 0; k < rings.size(); ++k) {
      if (k == outer) kept_outer = kept.size();
      if (!drop[k]) kept.push_back(std::move(rings[k]));
    }
    rings = std::move(kept);
    outer = kept_outer;
  }
  for (std::size_t k = 0; k < rings.size(); ++k)
    if (k != outer && !sm::point_in_ring(rings[outer], rings[k][0]))
      return std::fprintf(stderr, "bench_crude_world_geo: ring %zu lies outside the outer ring %zu on the chart\n", k,
                          outer),
             1;

  std::string out;
  out += fmt::format("// The GSHHG crude world ocean ({}; written by tests/bench/crude_world_geo.cpp, {} form):\n",
                     path, lines ? "Lines" : "BSplines");
  out += fmt::format("// {} rings, Curve Loop {} (Antarctica, round the chart's point at infinity) outer; {}\n",
                     rings.size(), outer + 1,
                     raw ? "raw (every point and ring)."
                         : fmt::format("{} spike points and {} rings whose B-spline crosses another left out.",
                                       spike_points, crossing_rings));
  out += fmt::format("Point(1) = {{0, 0, 0}};\nPoint(2) = {{0, 0, {:.16g}}};\nPolarSphere(1) = {{1, 2}};\n", radius);
  int p = 3, curve = 1;
  std::size_t points = 0;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const int first = p;
    for (const sm::Vec2& q : rings[k]) out += fmt::format("Point({}) = {{{:.16g}, {:.16g}, 0}};\n", p++, q.x, q.y);
    points += rings[k].size();
    if (lines) {
      const int c0 = curve;
      for (int i = first; i < p; ++i)
        out += fmt::format("Line({}) = {{{}, {}}};\n", curve++, i, i + 1 < p ? i + 1 : first);
      out += fmt::format("Curve Loop({}) = {{{}:{}}};\n", k + 1, c0, curve - 1);
    } else {
      out += fmt::format("BSpline({}) = {{{}:{}, {}}};\n", curve, first, p - 1, first);
      out += fmt::format("Curve Loop({}) = {{{}}};\n", k + 1, curve++);
    }
  }
  out += fmt::format("Plane Surface(1) = {{{}", outer + 1);
  for (std::size_t k = 0; k < rings.size(); ++k)
    if (k != outer) out += fmt::format(",{}{}", k % 20 == 0 ? "\n  " : " ", k + 1);
  out += "};\n";
  out += fmt::format("Field[1] = MathEval;\nField[1].F = \"{:.16g}\";\nBackground Field = 1;\n", size);
  out += "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\nMesh.MeshSizeExtendFromBoundary = 0;\n";
  std::ofstream f(argv[3]);
  f << out;
  if (!f.flush()) return std::fprintf(stderr, "bench_crude_world_geo: cannot write %s\n", argv[3]), 1;
  std::printf("%s: %zu rings, %zu points, %d curves, outer loop %zu; %zu spike points, %zu crossing rings left out\n",
              argv[3], rings.size(), points, curve - 1, outer + 1, spike_points, crossing_rings);
  return 0;
}
