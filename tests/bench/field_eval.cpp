// Field benchmark: Distance to ~1 million coastline samples answering
// 1 million queries, Threshold/Min/MathEval chains, MathEval against the same
// formula written in C++, bathymetry lookups, gradation build. One thread.
// Targets: Distance >= 1e6 queries/s; MathEval within 3x of hand-written C++.
// Times are thread CPU seconds.
#include <ctime>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "field/channel_width.h"
#include "field/distance.h"
#include "field/field_set.h"
#include "field/knn.h"
#include "field/lonlat_grid.h"
#include "field/math_expr.h"

using namespace sm;
using namespace sm::field;

namespace {

// CPU time of this thread: the machine is shared, and wall time would count
// the time other processes take from this core.
struct Clock {
  using time_point = double;
  static double now() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
};

double seconds_since(Clock::time_point t0) { return Clock::now() - t0; }

/// Coastline vertices of a GSHHG text file as lon/lat polylines, densified
/// by linear interpolation so that the total reaches about `target` points.
std::vector<Vec3> coastline_samples(const std::string& file, std::size_t target) {
  std::ifstream in(file);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", file.c_str());
    std::exit(1);
  }
  std::vector<std::vector<std::pair<double, double>>> segs;
  std::string line;
  std::size_t total = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '>') {
      segs.emplace_back();
      continue;
    }
    std::istringstream ls(line);
    double lon, lat;
    if (ls >> lon >> lat) {
      segs.back().push_back({lon, lat});
      ++total;
    }
  }
  const int k = static_cast<int>(std::ceil(static_cast<double>(target) / static_cast<double>(total)));
  std::vector<Vec3> out;
  for (const auto& s : segs)
    for (std::size_t i = 0; i < s.size(); ++i) {
      const auto [lon0, lat0] = s[i];
      const auto [lon1, lat1] = i + 1 < s.size() ? s[i + 1] : s[i];
      const int n = i + 1 < s.size() ? k : 1;
      for (int t = 0; t < n; ++t) {
        const double w = static_cast<double>(t) / n;
        out.push_back(point_of(lon0 + w * (lon1 - lon0), lat0 + w * (lat1 - lat0), 1));
      }
    }
  return out;
}

/// The rings of a GSHHG text file on the unit sphere, each segment cut into `k` pieces,
/// as ChannelWidth's coast chains (a repeated closing point dropped).
std::vector<CoastChain> coastline_rings(const std::string& file, int k) {
  std::ifstream in(file);
  std::vector<CoastChain> out;
  std::vector<std::pair<double, double>> ring;
  auto flush = [&] {
    if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    if (ring.size() < 3) {
      ring.clear();
      return;
    }
    CoastChain c;
    c.closed = true;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto [lon0, lat0] = ring[i];
      const auto [lon1, lat1] = ring[(i + 1) % ring.size()];
      const bool jump = std::fabs(lon1 - lon0) > 180;   // the date line: no interpolation across
      for (int t = 0; t < (jump ? 1 : k); ++t) {
        const double w = static_cast<double>(t) / k;
        c.points.push_back(point_of(lon0 + w * (lon1 - lon0), lat0 + w * (lat1 - lat0), 1));
      }
    }
    out.push_back(std::move(c));
    ring.clear();
  };
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '>') {
      flush();
      continue;
    }
    std::istringstream ls(line);
    double lon, lat;
    if (ls >> lon >> lat) ring.push_back({lon, lat});
  }
  flush();
  return out;
}

std::vector<Vec3> random_sphere(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec3> p(n);
  for (Vec3& v : p) {
    const Vec3 r{g(rng), g(rng), g(rng)};
    v = r / norm(r);
  }
  return p;
}

/// Queries near the coast: samples moved by up to ~0.01 (64 km) and put back on the sphere.
std::vector<Vec3> near_coast(const std::vector<Vec3>& coast, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, coast.size() - 1);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  std::vector<Vec3> p(n);
  for (Vec3& v : p) {
    const Vec3 c = coast[pick(rng)] + Vec3{u(rng), u(rng), u(rng)};
    v = c / norm(c);
  }
  return p;
}

void report(const char* what, std::size_t n, double s) {
  std::printf("%-58s %9.3f s  %12.0f queries/s\n", what, s, static_cast<double>(n) / s);
}

}  // namespace

int main() {
  const std::string data = SM_DATA_DIR;
  const std::size_t nq = 1000000;

  auto t0 = Clock::now();
  std::vector<Vec3> coast = coastline_samples(data + "/gshhg/world_i_A100.txt", 1000000);
  std::printf("coastline samples (world_i_A100, densified): %zu, parsed in %.3f s\n", coast.size(),
              seconds_since(t0));
  const std::vector<Vec3> q_uniform = random_sphere(nq, 1);
  const std::vector<Vec3> q_coast = near_coast(coast, nq, 2);
  std::vector<double> h(nq), ref(nq);

  // --- k-d tree variants ------------------------------------------------
  {
    t0 = Clock::now();
    KdTree exact(coast, {});
    std::printf("exact search (our k-d tree, leaf 8): build %.3f s\n",
                seconds_since(t0));
    t0 = Clock::now();
    exact.nearest(q_uniform, ref);
    report("  1M uniform queries on the sphere", nq, seconds_since(t0));
    t0 = Clock::now();
    exact.nearest(q_coast, h);
    report("  1M queries within ~60 km of the coast", nq, seconds_since(t0));
    KdTree plain(coast, {32, 0, false});
    t0 = Clock::now();
    plain.nearest(std::span<const Vec3>(q_coast).first(nq / 10), std::span<double>(h).first(nq / 10));
    report("  100k near-coast queries, unsorted, no previous answer to beat", nq / 10, seconds_since(t0));
    for (float eps : {0.05f, 0.25f}) {
      KdTree approx(coast, {32, eps, true});
      t0 = Clock::now();
      approx.nearest(q_uniform, h);
      const double s = seconds_since(t0);
      double worst = 0;
      for (std::size_t i = 0; i < nq; ++i) worst = std::max(worst, h[i] / ref[i] - 1);
      char label[96];
      std::snprintf(label, sizeof label, "  1M uniform, (1+%.2f)-approximate (worst +%.2f%%)", eps, 100 * worst);
      report(label, nq, s);
    }
  }

  // --- field chains through the FieldSet ---------------------------------
  FieldSet fs;
  fs.define(1, "MathEval");  // stand-in criterion for the chain (cheap)
  fs.set(1, "F", std::string("0.3 + 0.1 * x"));
  fs.define(2, "Threshold");
  fs.set(2, "InField", 10.0);
  fs.set(2, "SizeMin", 30.0 / 6371);
  fs.set(2, "SizeMax", 200.0 / 6371);
  fs.set(2, "DistMin", 0.0);
  fs.set(2, "DistMax", 500.0 / 6371);
  fs.define(3, "Min");
  fs.set(3, "FieldsList", std::vector<double>{1, 2});
  fs.define(4, "MathEval");
  fs.set(4, "F", std::string("F3 * (1 + 0.5 * Sin(3 * x) * Cos(2 * y)) + 0.01 * z^2"));
  BuildContext ctx;
  std::vector<Vec3> coast_copy = coast;
  // Distance as Field[10] from the same samples (Point tags 1..n through the context).
  ctx.point_position = [&](int tag) -> std::optional<Vec3> {
    return coast_copy[static_cast<std::size_t>(tag - 1)];
  };
  fs.define(10, "Distance");
  {
    std::vector<double> tags(coast.size());
    for (std::size_t i = 0; i < tags.size(); ++i) tags[i] = static_cast<double>(i + 1);
    fs.set(10, "PointsList", tags);
  }
  t0 = Clock::now();
  BuiltFields built = fs.build(4, ctx);
  std::printf("FieldSet build (Distance on %zu points + chain): %.3f s\n", coast.size(), seconds_since(t0));
  t0 = Clock::now();
  built.get(10)->eval(q_coast, h);
  report("Distance field (near-coast queries)", nq, seconds_since(t0));
  t0 = Clock::now();
  built.get(2)->eval(q_coast, h);
  report("Threshold(Distance)", nq, seconds_since(t0));
  t0 = Clock::now();
  built.get(3)->eval(q_coast, h);
  report("Min(MathEval, Threshold(Distance))", nq, seconds_since(t0));
  t0 = Clock::now();
  built.get(4)->eval(q_coast, h);
  report("MathEval(Min(MathEval, Threshold(Distance)))", nq, seconds_since(t0));

  // --- ChannelWidth: per-sample widths built once, one nearest query per point ---
  {
    std::vector<CoastChain> rings = coastline_rings(data + "/gshhg/world_i_A100.txt", 2);
    std::size_t samples = 0;
    for (const CoastChain& c : rings) samples += c.points.size();
    t0 = Clock::now();
    // Widths up to 2 x 50 km (Mesh.ElementsAcrossChannels 2 with a 50 km largest size).
    FieldPtr cw = make_channel_width_field(std::move(rings), {2, 0, 50.0 / 6371});
    std::printf("ChannelWidth build (world_i_A100, %zu samples in rings, widths to 100 km): %.3f s\n", samples,
                seconds_since(t0));
    t0 = Clock::now();
    cw->eval(q_uniform, h);
    report("ChannelWidth, uniform queries", nq, seconds_since(t0));
    t0 = Clock::now();
    cw->eval(q_coast, h);
    report("ChannelWidth, near-coast queries", nq, seconds_since(t0));
  }

  // --- MathEval against the same formula in C++ --------------------------
  {
    const char* formula = "F1 * (1 + 0.5 * Sin(3 * x) * Cos(2 * y)) + 0.01 * z^2 + sqrt(x*x + y*y)";
    MathExpr e = MathExpr::compile(formula);
    std::vector<double> f1(nq);
    for (std::size_t i = 0; i < nq; ++i) f1[i] = 0.01 + 1e-9 * static_cast<double>(i);
    std::vector<std::span<const double>> cols = {f1};
    double best_m = 1e9, best_c = 1e9;
    double check = 0;
    for (int rep = 0; rep < 3; ++rep) {
      t0 = Clock::now();
      e.eval(q_uniform, cols, h);
      best_m = std::min(best_m, seconds_since(t0));
      t0 = Clock::now();
      for (std::size_t i = 0; i < nq; ++i) {
        const Vec3& p = q_uniform[i];
        ref[i] = f1[i] * (1 + 0.5 * std::sin(3 * p.x) * std::cos(2 * p.y)) + 0.01 * std::pow(p.z, 2) +
                 std::sqrt(p.x * p.x + p.y * p.y);
      }
      best_c = std::min(best_c, seconds_since(t0));
      for (std::size_t i = 0; i < nq; i += 1000) check = std::max(check, std::fabs(h[i] - ref[i]));
    }
    std::printf("MathEval \"%s\"\n", formula);
    report("  compiled MathEval", nq, best_m);
    report("  hand-written C++", nq, best_c);
    std::printf("  ratio MathEval / C++ = %.2f (max |difference| %.2g)\n", best_m / best_c, check);
  }

  // --- bathymetry lookups -------------------------------------------------
  for (const char* output : {"depth", "wavelength", "hessian"}) {
    FieldSet b;
    b.define(1, "Bathymetry");
    b.set(1, "FileName", data + "/bathymetry/etopo5_global_0.25deg.nc");
    b.set(1, "Output", std::string(output));
    t0 = Clock::now();
    BuiltFields bb = b.build(1, {});
    const double load = seconds_since(t0);
    t0 = Clock::now();
    bb.get(1)->eval(q_uniform, h);
    char label[96];
    std::snprintf(label, sizeof label, "Bathymetry %s, global 0.25 deg (load %.3f s)", output, load);
    report(label, nq, seconds_since(t0));
  }

  // --- gradation ------------------------------------------------------------
  {
    FieldSet g;
    g.define(1, "Bathymetry");
    g.set(1, "FileName", data + "/bathymetry/etopo5_global_1deg.nc");
    g.set(1, "Output", std::string("wavelength"));
    g.set(1, "WaveLengthMin", 0.05);
    g.define(2, "Gradation");
    g.set(2, "InField", 1.0);
    g.set(2, "Rate", 0.2);
    g.set(2, "Resolution", 0.25);
    t0 = Clock::now();
    BuiltFields gb = g.build(2, {});
    std::printf("Gradation build, 0.25 deg global grid (1441 x 721 nodes): %.3f s\n", seconds_since(t0));
    t0 = Clock::now();
    gb.get(2)->eval(q_uniform, h);
    report("Gradation lookups", nq, seconds_since(t0));
  }
  return 0;
}
