// Every field kind, and the size policy, evaluated from several threads at once (`-nt`: parts of one face refined
// concurrently) give the same bits as a serial evaluation, and so do netCDF grids read from several threads. Run under
// ThreadSanitizer (build-*-tsan, docs/fields.md "Threads") this also shows there is no race.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include <doctest/doctest.h>
#include <fmt/format.h>

#include "base/parallel.h"
#include "field/lonlat_grid.h"
#include "field/size_policy.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::repo_data;

namespace {

constexpr int kThreads = 4;

std::vector<Vec3> read_coast(const std::string& rel) {
  std::ifstream in(repo_data(rel));
  REQUIRE(in);
  std::vector<Vec3> coast;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == '>') continue;
    std::istringstream ls(line);
    double lon, lat;
    ls >> lon >> lat;
    coast.push_back(point_of(lon, lat, 1));
  }
  return coast;
}

/// Queries on the unit sphere: uniform ones (mostly far from the coast, the Distance
/// field's coarse bucket search), ones just off the coast (its seeded fine search),
/// coast samples themselves (distance 0), the poles and the date line.
std::vector<Vec3> queries(const std::vector<Vec3>& coast) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0, 1);
  std::vector<Vec3> q;
  for (int i = 0; i < 1500; ++i) {
    const Vec3 p{g(rng), g(rng), g(rng)};
    q.push_back(p / norm(p));
  }
  std::uniform_int_distribution<std::size_t> pick(0, coast.size() - 1);
  for (int i = 0; i < 1500; ++i) {
    const Vec3 p = coast[pick(rng)] + 2e-3 * Vec3{g(rng), g(rng), g(rng)};
    q.push_back(p / norm(p));
  }
  for (int i = 0; i < 50; ++i) q.push_back(coast[pick(rng)]);
  for (double lat = -90; lat <= 90; lat += 15) q.push_back(point_of(180, lat, 1));
  q.push_back(point_of(-180, 0, 1));
  return q;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  return true;
}

/// One field of every kind, on real data: the GSHHG world coastline for Distance and
/// ETOPO5 for Bathymetry and Structured. Returns their ids (every kind at least once).
std::vector<int> define_all(FieldSet& fs, std::size_t coast_points) {
  const double r = 6371e3;
  int id = 0;
  std::vector<int> ids;
  auto def = [&](const char* kind) {
    fs.define(++id, kind);
    ids.push_back(id);
    return id;
  };
  const int dist = def("Distance");
  std::vector<double> tags(coast_points);
  for (std::size_t i = 0; i < tags.size(); ++i) tags[i] = static_cast<double>(i + 1);
  fs.set(dist, "PointsList", tags);
  // BoundaryLayer's scalar size grows with the distance to the same points.
  const int layer = def("BoundaryLayer");
  fs.set(layer, "PointsList", tags);
  fs.set(layer, "Size", 1e-3);
  fs.set(layer, "Ratio", 1.2);
  fs.set(layer, "Thickness", 1.0);
  fs.set(layer, "SizeFar", 10.0);

  // The coast as one chain (ctx.curve_chains below), widths searched up to 128 km.
  const int channel = def("ChannelWidth");
  fs.set(channel, "CurvesList", std::vector<double>{1});
  fs.set(channel, "SizeMax", 64e3 / r);

  const int thr = def("Threshold");
  fs.set(thr, "InField", static_cast<double>(dist));
  fs.set(thr, "SizeMin", 30e3 / r);
  fs.set(thr, "SizeMax", 200e3 / r);
  fs.set(thr, "DistMin", 0.0);
  fs.set(thr, "DistMax", 500e3 / r);
  fs.set(thr, "Sigmoid", 1.0);

  const int depth = def("Bathymetry");
  fs.set(depth, "FileName", repo_data("bathymetry/etopo5_global_1deg.nc"));
  fs.set(depth, "Radius", 1.0);
  const int step = def("TimeStep");
  fs.set(step, "DepthField", static_cast<double>(depth));
  fs.set(step, "Dt", 60.0);
  const int wave = def("Bathymetry");
  fs.set(wave, "FileName", repo_data("bathymetry/etopo5_global_1deg.asc"));
  fs.set(wave, "Output", std::string("wavelength"));
  fs.set(wave, "WaveLengthMin", 20e3 / r);
  fs.set(wave, "DepthRef", 1000.0);
  const int hess = def("Bathymetry");
  fs.set(hess, "FileName", repo_data("bathymetry/etopo5_global_1deg.nc"));
  fs.set(hess, "Output", std::string("hessian"));

  // Field inputs, variadic functions and rand() (a hash of the point, no generator state).
  const int expr = def("MathEval");
  fs.set(expr, "F", fmt::format("min(F{}, F{}/1e4, 0.2) + 0.01*Sin(7*x)*Cos(5*y) + 0.001*rand() + "
                                "1e-3*med(x, y, z, F{}/1e6) + 0.01*sqrt(abs(z))", dist, depth, hess));

  const int mn = def("Min");
  fs.set(mn, "FieldsList", std::vector<double>{static_cast<double>(thr), static_cast<double>(wave)});
  const int mx = def("Max");
  fs.set(mx, "FieldsList", std::vector<double>{static_cast<double>(thr), static_cast<double>(expr)});
  const int mna = def("MinAniso");
  fs.set(mna, "FieldsList", std::vector<double>{static_cast<double>(mn), static_cast<double>(mx)});

  const int grad = def("Gradation");
  fs.set(grad, "InField", static_cast<double>(mn));
  fs.set(grad, "Rate", 0.2);
  fs.set(grad, "Resolution", 2.0);

  const int restrict = def("Restrict");
  fs.set(restrict, "InField", static_cast<double>(thr));
  fs.set(restrict, "SurfacesList", std::vector<double>{1});
  const int constant = def("Constant");
  fs.set(constant, "VIn", 0.01);
  fs.set(constant, "VOut", 0.05);
  fs.set(constant, "SurfacesList", std::vector<double>{1, 3});

  const int box = def("Box");
  for (const char* o : {"XMin", "YMin", "ZMin"}) fs.set(box, o, -0.3);
  for (const char* o : {"XMax", "YMax", "ZMax"}) fs.set(box, o, 0.6);
  fs.set(box, "VIn", 0.01);
  fs.set(box, "VOut", 0.1);
  fs.set(box, "Thickness", 0.4);
  const int ball = def("Ball");
  fs.set(ball, "XCenter", 0.5);
  fs.set(ball, "ZCenter", 0.7);
  fs.set(ball, "Radius", 0.4);
  fs.set(ball, "Thickness", 0.3);
  fs.set(ball, "VIn", 0.02);
  fs.set(ball, "VOut", 0.2);
  const int cyl = def("Cylinder");
  fs.set(cyl, "XAxis", 0.3);
  fs.set(cyl, "YAxis", 0.4);
  fs.set(cyl, "ZAxis", 0.9);
  fs.set(cyl, "Radius", 0.5);
  fs.set(cyl, "VIn", 0.03);
  fs.set(cyl, "VOut", 0.3);

  // Structured on the GBR relief, reached through LonLat (radians) and Param (degrees).
  const int grid = def("Structured");
  fs.set(grid, "FileName", repo_data("bathymetry/etopo5_gbr_5min.gmsh_structured.txt"));
  fs.set(grid, "TextFormat", 1.0);
  const int param = def("Param");
  fs.set(param, "InField", static_cast<double>(grid));
  fs.set(param, "FX", std::string("x*180/Pi"));
  fs.set(param, "FY", std::string("y*180/Pi"));
  const int lonlat = def("LonLat");
  fs.set(lonlat, "InField", static_cast<double>(param));
  fs.set(lonlat, "RadiusStereo", 1.0);

  const int gradient = def("Gradient");
  fs.set(gradient, "InField", static_cast<double>(wave));
  fs.set(gradient, "Kind", 3.0);
  fs.set(gradient, "Delta", 1e-3);
  const int lap = def("Laplacian");
  fs.set(lap, "InField", static_cast<double>(thr));
  fs.set(lap, "Delta", 1e-3);
  const int mean = def("Mean");
  fs.set(mean, "InField", static_cast<double>(restrict));
  fs.set(mean, "Delta", 1e-3);
  const int curv = def("Curvature");
  fs.set(curv, "InField", static_cast<double>(ball));
  fs.set(curv, "Delta", 1e-3);
  const int eig = def("MaxEigenHessian");
  fs.set(eig, "InField", static_cast<double>(depth));
  fs.set(eig, "Delta", 1e-3);
  return ids;
}

}  // namespace

TEST_CASE("field threads: every kind gives the serial bits from 4 threads at once") {
  const std::vector<Vec3> coast = read_coast("gshhg/world_l.txt");
  REQUIRE(coast.size() > 50000);
  BuildContext ctx;
  ctx.point_position = [&](int tag) -> std::optional<Vec3> {
    if (tag < 1 || tag > static_cast<int>(coast.size())) return std::nullopt;
    return coast[static_cast<std::size_t>(tag - 1)];
  };
  ctx.curve_chains = [&](const std::vector<int>&) -> std::optional<std::vector<CoastChain>> {
    return std::vector<CoastChain>{{coast, false}};
  };
  FieldSet fs;
  const std::vector<int> ids = define_all(fs, coast.size());
  std::set<std::string> kinds_used;
  for (int id : ids) kinds_used.insert(fs.options(id).kind().name);
  REQUIRE(kinds_used.size() == kinds().size());
  const BuiltFields built = fs.build_all(ctx);
  const std::vector<Vec3> q = queries(coast);
  const std::size_t n = q.size();

  // No entity, a listed surface (Restrict and Constant apply) and an unlisted one.
  const EntityRef on_listed{2, 1}, on_other{2, 2};
  const std::vector<const EntityRef*> modes = {nullptr, &on_listed, &on_other};
  struct Case {
    int id;
    const EntityRef* on;
  };
  std::vector<Case> cases;
  for (int id : ids)
    for (const EntityRef* on : modes) cases.push_back({id, on});
  auto eval = [&](const Case& c, std::span<const Vec3> pts, std::span<double> h) {
    eval_input(*built.get(c.id), c.on, pts, h);
  };

  std::vector<std::vector<double>> serial(cases.size(), std::vector<double>(n));
  for (std::size_t k = 0; k < cases.size(); ++k) eval(cases[k], q, serial[k]);
  // Each field computes something that varies over the queries, so equal bits mean
  // something. Constant and Cylinder take two values (no ramp); Structured, given unit-
  // sphere points directly, is its edge value, and varies through LonLat and Param.
  for (int id : ids) {
    std::set<std::uint64_t> distinct;
    for (std::size_t k = 0; k < cases.size(); ++k)
      if (cases[k].id == id)
        for (double v : serial[k]) distinct.insert(std::bit_cast<std::uint64_t>(v));
    const std::string& kind = fs.options(id).kind().name;
    INFO("Field[" << id << "] " << kind);
    CHECK(distinct.size() >= (kind == "Structured" ? 1u : kind == "Constant" || kind == "Cylinder" ? 2u : 20u));
  }

  SUBCASE("every thread evaluates the whole set of every field") {
    std::vector<std::vector<std::vector<double>>> got(
        kThreads, std::vector<std::vector<double>>(cases.size(), std::vector<double>(n)));
    parallel_for_chunks(kThreads, kThreads, 1, [&](std::size_t t, std::size_t) {
      for (std::size_t k = 0; k < cases.size(); ++k) eval(cases[k], q, got[t][k]);
    });
    for (int t = 0; t < kThreads; ++t)
      for (std::size_t k = 0; k < cases.size(); ++k) {
        INFO("thread " << t << ", Field[" << cases[k].id << "] " << fs.options(cases[k].id).kind().name);
        CHECK(same_bits(got[static_cast<std::size_t>(t)][k], serial[k]));
      }
  }

  SUBCASE("threads evaluate disjoint chunks, of all fields interleaved") {
    for (std::size_t chunk : {7u, 250u}) {
      const std::size_t per_case = (n + chunk - 1) / chunk;
      std::vector<std::vector<double>> got(cases.size(), std::vector<double>(n));
      parallel_for_chunks(kThreads, cases.size() * per_case, 1, [&](std::size_t item, std::size_t) {
        const std::size_t k = item % cases.size(), b = item / cases.size() * chunk;
        const std::size_t e = std::min(n, b + chunk);
        eval(cases[k], std::span<const Vec3>(q).subspan(b, e - b), std::span<double>(got[k]).subspan(b, e - b));
      });
      for (std::size_t k = 0; k < cases.size(); ++k) {
        INFO("chunk " << chunk << ", Field[" << cases[k].id << "] " << fs.options(cases[k].id).kind().name);
        CHECK(same_bits(got[k], serial[k]));
      }
    }
  }
}

TEST_CASE("field threads: the size policy from 4 threads equals the serial sizes") {
  SizePolicyOptions o;
  o.min = 0.004;
  o.max = 0.03;
  o.factor = 0.9;
  o.from_curvature = 12;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(1e-4, 0.05);
  const std::size_t n = 5000;
  std::vector<SizeQuery> qs(n);
  std::vector<double> boundary(n);
  for (std::size_t i = 0; i < n; ++i) {
    SizeQuery& q = qs[i];
    q.bbox_diag = 2;
    q.entity_dim = static_cast<int>(i % 3);
    if (i % 5) q.point_lc = u(rng);
    if (i % 7) q.end_lc0 = u(rng);
    if (i % 11) q.end_lc1 = u(rng);
    q.t = static_cast<double>(i) / n;
    if (i % 2) q.curvature = 1 / u(rng);
    if (i % 13) q.background = u(rng);
    boundary[i] = u(rng);
  }
  auto size = [&](std::size_t i) {
    return surface_target(o, final_size(o, qs[i]).size,
                          i % 4 ? std::optional<double>(boundary[i]) : std::nullopt);
  };
  std::vector<double> serial(n), got(n);
  for (std::size_t i = 0; i < n; ++i) serial[i] = size(i);
  parallel_for_chunks(kThreads, n, 3, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) got[i] = size(i);
  });
  CHECK(same_bits(got, serial));
  std::set<double> distinct(serial.begin(), serial.end());
  CHECK(distinct.size() > 100);
}

// libnetcdf itself is not thread-safe (two reads at once fail with "Not a valid ID" or
// crash); read_netcdf_grid serialises its calls, so grids may be read from any thread.
TEST_CASE("field threads: netCDF grids read from 8 threads at once equal the serial reads") {
  const std::vector<std::string> files = {
      repo_data("bathymetry/etopo5_global_1deg.nc"), repo_data("bathymetry/etopo5_gbr_5min.nc"),
      repo_data("bathymetry/etopo60.cdf"), repo_data("bathymetry/etopo5_nw_europe_5min.nc")};
  std::vector<LonLatGrid> serial;
  for (const std::string& f : files) serial.push_back(read_netcdf_grid(f, {}));
  constexpr std::size_t kReaders = 8, kReads = 64;
  std::vector<std::vector<double>> got(kReaders * kReads);
  parallel_for_chunks(static_cast<int>(kReaders), got.size(), 1, [&](std::size_t k, std::size_t) {
    got[k] = read_netcdf_grid(files[k % files.size()], {}).v;
  });
  for (std::size_t k = 0; k < got.size(); ++k) {
    INFO(files[k % files.size()]);
    CHECK(same_bits(got[k], serial[k % files.size()].v));
  }
}
