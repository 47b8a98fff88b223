// Benchmark: the whole curve set of GSHHG world_i_A100.txt (192,842 points, 1,440
// coastlines) as closed BSplines in unit-PolarSphere (u,v) coordinates: build the model
// (points, curves, loops, one Plane Surface with Antarctica outer and the hole checks), then
// time curve evaluation on the largest curve (Eurasia, 35k control points) against a
// 100-point curve to show that evaluation does not depend on the number of control points.
#include "geo/model.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace sm;
using namespace sm::geo;

namespace {

struct Segment {
  bool wraps_pole = false;
  std::vector<LonLat> pts;
};

// A tiny reader of the GSHHG text export for this benchmark only.
std::vector<Segment> read_segments(const std::string& path) {
  std::ifstream in(path);
  std::vector<Segment> segs;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '>') {
      segs.emplace_back();
      segs.back().wraps_pole = line.find("wraps_pole=1") != std::string::npos;
      continue;
    }
    LonLat p;
    if (std::sscanf(line.c_str(), "%lf %lf", &p.lon, &p.lat) == 2 && !segs.empty()) segs.back().pts.push_back(p);
  }
  return segs;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main() {
  const std::string path = std::string(SM_DATA_DIR) + "/gshhg/world_i_A100.txt";
  auto t0 = std::chrono::steady_clock::now();
  const std::vector<Segment> segs = read_segments(path);
  const double t_read = seconds_since(t0);
  if (segs.empty()) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    return 1;
  }

  t0 = std::chrono::steady_clock::now();
  Model m;
  bool ok = m.add_point(1, {0, 0, 0}).ok() && m.add_point(2, {0, 0, 1}).ok() && m.add_polar_sphere(1, 1, 2).ok();
  const PolarSphere ps = *m.geometry(1)->polar();
  int outer = 0, largest = 0, smallest = 0;
  std::size_t largest_n = 0, smallest_n = 1u << 30, npts = 0;
  std::vector<int> loops;
  for (const Segment& s : segs) {
    const int first = m.new_point_tag();
    std::vector<int> ids;
    ids.reserve(s.pts.size());
    // The last vertex repeats the first on the sphere: close on the first tag.
    for (std::size_t i = 0; i + 1 < s.pts.size(); ++i) {
      const Vec2 uv = ps.param_from_lonlat(s.pts[i]);
      const int t = m.new_point_tag();
      ok = ok && m.add_point(t, {uv.x, uv.y, 0}).ok();
      ids.push_back(t);
    }
    ids.push_back(first);
    npts += ids.size() - 1;
    const int c = m.new_curve_tag();
    ok = ok && m.add_curve(c, CurveKind::BSpline, ids).ok();
    const int l = m.new_loop_tag();
    ok = ok && m.add_curve_loop(l, {c}).ok();
    if (s.wraps_pole) outer = l;
    else loops.push_back(l);
    if (ids.size() > largest_n) largest_n = ids.size(), largest = c;
    if (ids.size() >= 100 && ids.size() < smallest_n) smallest_n = ids.size(), smallest = c;
  }
  const double t_curves = seconds_since(t0);
  loops.insert(loops.begin(), outer);
  t0 = std::chrono::steady_clock::now();
  const int surface_tag = m.new_surface_tag();
  const GeoStatus st = m.add_plane_surface(surface_tag, loops);
  const double t_surface = seconds_since(t0);
  ok = ok && st.ok();
  std::printf("world_i_A100: %zu coastlines, %zu points\n", segs.size(), npts);
  std::printf("  read (bench reader)          %8.3f s\n", t_read);
  std::printf("  points + BSplines + loops    %8.3f s\n", t_curves);
  std::printf("  plane surface (hole checks)  %8.3f s\n", t_surface);
  std::printf("  model build total            %8.3f s  (%s)\n", t_curves + t_surface,
              ok ? "valid" : (st.ok() ? "error" : geo::summary(st.error()).c_str()));

  // Evaluation cost per call: same number of calls on a 35k-point and a ~100-point curve.
  const int calls = 2'000'000;
  double sink = 0;
  for (int c : {largest, smallest}) {
    const Curve& shape = *m.curve(c)->shape;
    t0 = std::chrono::steady_clock::now();
    std::uint64_t x = 88172645463325252ull;
    for (int i = 0; i < calls; ++i) {
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      const double t = static_cast<double>(x >> 11) * 0x1.0p-53;
      const Jet3 j = shape.eval(t);
      sink += j.p.x + j.d1.y + j.d2.z;
    }
    const double dt = seconds_since(t0);
    std::printf("  eval point+d1+d2, %6zu control points: %6.1f ns/call\n", m.curve(c)->points.size() - 1,
                1e9 * dt / calls);
  }
  std::printf("  (checksum %.3g)\n", sink);

  // Whole-model edits at this size: Coherence and Recursive Delete. Coherence merges 4
  // points: 4 rings of this file repeat a vertex non-consecutively (out-and-back spikes or
  // pinches where GMT joined bin pieces, at lon -100, -75, 5 and 0; segments 44, 158, 681, 1).
  t0 = std::chrono::steady_clock::now();
  const int merged = m.coherence();
  std::printf("  Coherence                    %8.3f s  (%d merged)\n", seconds_since(t0), merged);
  t0 = std::chrono::steady_clock::now();
  ok = ok && m.remove({{2, surface_tag}}, true).ok();
  std::printf("  Recursive Delete of the face %8.3f s  (%zu points, %zu curves left)\n", seconds_since(t0),
              m.vertices().size(), m.curves().size());
  ok = ok && m.curves().empty() && m.vertices().size() == 2;
  return ok ? 0 : 1;
}
