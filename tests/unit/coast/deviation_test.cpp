// The coast curve held within its bound of the source points (coast/deviation.h), on
// synthetic shorelines whose answer is known: a broad headland the B-spline cuts, a
// spike narrower than the accuracy that must stay out, and a strait whose width must
// come out as it is.
#include "coast/deviation.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace sm;
using namespace sm::coast;

namespace {

constexpr double kR = 6371e3;
constexpr double kM = 180.0 / (geo::kPi * kR);   // degrees of latitude per metre

// A closed curve from lon/lat points (degrees) near (0, 45), with constant gamma and the
// coarsening's kind of control points: every `step`-th point.
WorkCurve curve_of(const std::vector<geo::LonLat>& pts, double gamma, std::size_t step) {
  WorkCurve c;
  c.full = pts;
  c.periodic = true;
  c.gamma.assign(pts.size(), gamma);
  const geo::PolarSphere unit({0, 0, 0}, 1.0);
  for (const auto& p : pts) c.uv.push_back(unit.param_from_lonlat(p));
  for (std::size_t i = 0; i < pts.size(); i += step) c.keep.push_back(static_cast<std::uint32_t>(i));
  return c;
}

// A 200 km square island (x east, y north in metres round (0, 45)) with a headland on its
// north side: a triangle `width` wide at its base and `height` high, points every 2 km.
std::vector<geo::LonLat> island_with_headland(double width, double height) {
  std::vector<std::pair<double, double>> corners = {{-100e3, -100e3}, {100e3, -100e3}, {100e3, 100e3},
                                                    {width / 2, 100e3}, {0, 100e3 + height}, {-width / 2, 100e3},
                                                    {-100e3, 100e3}};
  std::vector<geo::LonLat> pts;
  const double coslat = std::cos(45.0 * geo::kDegToRad);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const auto [x0, y0] = corners[k];
    const auto [x1, y1] = corners[(k + 1) % corners.size()];
    const int n = std::max(1, static_cast<int>(std::hypot(x1 - x0, y1 - y0) / 2e3));
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      pts.push_back({(x0 + t * (x1 - x0)) * kM / coslat, 45.0 + (y0 + t * (y1 - y0)) * kM});
    }
  }
  // Counter-clockwise as drawn: south side east, east side north, north side west.
  return pts;
}

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

}  // namespace

TEST_CASE("deviation: a headland cut by the B-spline gets its points back, within the bound") {
  // 60 km wide and 40 km high, control points every 30 km: the spline through them cuts
  // the tip by 12 km, more than half the accuracy of 20 km.
  WorkCurve c = curve_of(island_with_headland(60e3, 40e3), 20e3, 15);
  DeviationOptions opt;
  opt.radius = kR;
  const double before = max_of(source_distances(c, opt));
  CHECK(before > 10e3 * 1.1);
  std::vector<WorkCurve> curves{c};
  const DeviationReport rep = bound_deviation(curves, opt);
  CHECK(rep.points_added > 0);
  CHECK(rep.max_before == doctest::Approx(before));
  CHECK(rep.left_over_bound == 0);
  CHECK(rep.narrow_features == 0);
  const std::vector<double> after = source_distances(curves[0], opt);
  CHECK(max_of(after) <= 10e3);
  CHECK(rep.max == doctest::Approx(max_of(after)));
  CHECK(std::is_sorted(curves[0].keep.begin(), curves[0].keep.end()));
}

TEST_CASE("deviation: MaxDeviation in metres, and a factor of 0 measures only") {
  WorkCurve c = curve_of(island_with_headland(60e3, 40e3), 30e3, 15);
  DeviationOptions opt;
  opt.radius = kR;
  opt.fixed = 2e3;
  std::vector<WorkCurve> curves{c};
  const DeviationReport rep = bound_deviation(curves, opt);
  CHECK(rep.max <= 2e3);
  DeviationOptions off;
  off.radius = kR;
  off.factor = 0;
  std::vector<WorkCurve> untouched{c};
  const DeviationReport none = bound_deviation(untouched, off);
  CHECK(none.points_added == 0);
  CHECK(untouched[0].keep == c.keep);
  CHECK(none.max == doctest::Approx(none.max_before));
}

TEST_CASE("deviation: a spike narrower than the accuracy makes no sharp corner") {
  // 4 km wide and 60 km long with gamma 30 km, left out by the coarsening (no control point
  // on it): its sides put back whole would make a corner of 4 degrees at the tip.
  WorkCurve c = curve_of(island_with_headland(4e3, 60e3), 30e3, 15);
  const double base = 45.0 + 100e3 * kM + 1e-9;
  std::erase_if(c.keep, [&](std::uint32_t k) { return c.full[k].lat > base; });
  DeviationOptions opt;
  opt.radius = kR;
  std::vector<WorkCurve> curves{c};
  const DeviationReport rep = bound_deviation(curves, opt);
  // The spike comes back only as far as a corner of 30 degrees allows: the rest is
  // reported as too narrow, and everything else is within the bound.
  CHECK(rep.points_added > 0);
  CHECK(rep.narrow_features >= 1);
  CHECK(rep.max <= 15e3);
  const std::vector<std::uint32_t>& keep = curves[0].keep;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const Vec2 a = curves[0].uv[keep[(i + keep.size() - 1) % keep.size()]], b = curves[0].uv[keep[i]],
               d = curves[0].uv[keep[(i + 1) % keep.size()]];
    const Vec2 u = a - b, w = d - b;
    CHECK(std::atan2(std::abs(u.x * w.y - u.y * w.x), u.x * w.x + u.y * w.y) >= 30.0 * geo::kDegToRad - 1e-9);
  }
}

TEST_CASE("deviation: the same curve for every thread count") {
  std::vector<WorkCurve> one, four;
  for (int i = 0; i < 8; ++i) one.push_back(curve_of(island_with_headland(20e3 + 10e3 * i, 40e3), 30e3, 13 + i));
  four = one;
  DeviationOptions opt;
  opt.radius = kR;
  bound_deviation(one, opt);
  opt.threads = 4;
  bound_deviation(four, opt);
  for (std::size_t i = 0; i < one.size(); ++i) CHECK(one[i].keep == four[i].keep);
}

TEST_CASE("deviation: a bend of the data with no point left between its control points") {
  // A square island 100 km a side, its data only the corners and the sides' middles (50 km
  // apart, all kept at gamma 20 km): the spline cuts each right-angled corner by 11.8 km,
  // over the bound of 10 km, and no source point lies between the control points. The
  // data's own segments next to the corners are split at their middle (points of the
  // shoreline) until the curve comes within the bound.
  std::vector<geo::LonLat> pts;
  const double coslat = std::cos(45.0 * geo::kDegToRad);
  for (auto [x, y] : std::vector<std::pair<double, double>>{{-50e3, -50e3}, {0, -50e3}, {50e3, -50e3}, {50e3, 0},
                                                            {50e3, 50e3}, {0, 50e3}, {-50e3, 50e3}, {-50e3, 0}})
    pts.push_back({x * kM / coslat, 45.0 + y * kM});
  WorkCurve c = curve_of(pts, 20e3, 1);
  DeviationOptions opt;
  opt.radius = kR;
  const double before = max_of(source_distances(c, opt));
  CHECK(before > 11e3);
  std::vector<WorkCurve> curves{c};
  const DeviationReport rep = bound_deviation(curves, opt);
  CHECK(rep.segments_split > 0);
  CHECK(rep.left_over_bound == 0);
  CHECK(rep.narrow_features == 0);
  CHECK(rep.max <= 10e3);
  // The new points lie on the data's segments, and every one is a control point.
  const WorkCurve& out = curves[0];
  CHECK(out.full.size() > pts.size());
  CHECK(out.keep.size() == out.full.size());
  CHECK(std::is_sorted(out.keep.begin(), out.keep.end()));
  for (const geo::LonLat& p : out.full) {
    const double x = p.lon * coslat / kM, y = (p.lat - 45.0) / kM;
    CHECK(std::min(std::abs(std::abs(x) - 50e3), std::abs(std::abs(y) - 50e3)) < 1e3);   // on the square
  }
  CHECK(max_of(source_distances(out, opt)) <= 10e3);
}

TEST_CASE("deviation: the figures kept from the rounds are those of a fresh scan of every curve") {
  // The pass reads its final figures from each segment's result kept since it was last
  // scanned (coast/deviation.cpp); a fresh scan of the curves as they end up must give
  // the same numbers to the last bit: after all the rounds, after rounds cut short (the
  // segments near the last points put back scanned at the end), on closed curves and on a
  // piece.
  std::vector<WorkCurve> base;
  for (int i = 0; i < 5; ++i)
    base.push_back(curve_of(island_with_headland(20e3 + 15e3 * i, 30e3 + 5e3 * i), 25e3, 11 + 2 * i));
  WorkCurve piece = curve_of(island_with_headland(50e3, 45e3), 25e3, 14);
  piece.periodic = false;
  if (piece.keep.back() != piece.full.size() - 1)
    piece.keep.push_back(static_cast<std::uint32_t>(piece.full.size() - 1));
  base.push_back(piece);
  for (const int rounds : {1, 2, 32}) {
    CAPTURE(rounds);
    std::vector<WorkCurve> curves = base;
    DeviationOptions opt;
    opt.radius = kR;
    opt.max_rounds = rounds;
    const DeviationReport rep = bound_deviation(curves, opt);
    CHECK(rep.points_added > 0);
    std::vector<double> all;
    double max = 0;
    for (const WorkCurve& c : curves) {
      const std::vector<double> d = source_distances(c, opt);
      all.insert(all.end(), d.begin(), d.end());
      max = std::max(max, max_of(d));
    }
    const std::size_t k = std::min(all.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(all.size())));
    std::nth_element(all.begin(), all.begin() + static_cast<long>(k), all.end());
    CHECK(rep.p95 == all[k]);
    if (rep.narrow_features == 0) CHECK(rep.max == max);
  }
}

TEST_CASE("deviation: each source point's distance is the nearest of the three spans near its segment") {
  // The pass measures a source point against the curve near its control-polygon segment:
  // the spans before it, along it and after it, sampled at kSamples + 1 points each
  // (coast/deviation.cpp). Here the same samples are made by hand and every segment of
  // their polyline measured, with no grouping nor skipping: the pass's distances must be
  // the same numbers, on closed curves and on a piece (its end points tripled).
  constexpr int kSamples = 8;
  DeviationOptions opt;
  opt.radius = kR;
  const geo::PolarSphere ps({0, 0, 0}, kR);
  std::vector<WorkCurve> curves;
  for (int i = 0; i < 3; ++i) curves.push_back(curve_of(island_with_headland(20e3 + 20e3 * i, 25e3 + 10e3 * i), 25e3, 7 + 3 * i));
  WorkCurve piece = curve_of(island_with_headland(40e3, 35e3), 25e3, 9);
  piece.periodic = false;
  if (piece.keep.back() != piece.full.size() - 1)
    piece.keep.push_back(static_cast<std::uint32_t>(piece.full.size() - 1));
  curves.push_back(piece);
  for (const WorkCurve& c : curves) {
    CAPTURE(c.periodic);
    const long m = static_cast<long>(c.keep.size()), n = static_cast<long>(c.full.size());
    auto control = [&](long k) {
      const long i = c.periodic ? ((k % m) + m) % m : std::clamp(k, 0L, m - 1);
      return c.uv[c.keep[static_cast<std::size_t>(i)]];
    };
    auto span = [&](long k, std::vector<Vec3>& line, bool first) {
      const Vec2 a = control(k - 1), b = control(k), cc = control(k + 1), d = control(k + 2);
      for (int i = first ? 0 : 1; i <= kSamples; ++i) {
        const double t = static_cast<double>(i) / kSamples, u = 1 - t;
        const double wa = u * u * u, wb = 3 * t * t * t - 6 * t * t + 4, wc = -3 * t * t * t + 3 * t * t + 3 * t + 1,
                     wd = t * t * t;
        line.push_back(ps.point((wa * a + wb * b + wc * cc + wd * d) / 6.0));
      }
    };
    const std::vector<double> got = source_distances(c, opt);
    REQUIRE(got.size() == c.full.size());
    const long segments = c.periodic ? m : m - 1;
    std::size_t checked = 0;
    for (long s = 0; s < segments; ++s) {
      std::vector<Vec3> line;
      span(s - 1, line, true);
      span(s, line, false);
      span(s + 1, line, false);
      const long a = c.keep[static_cast<std::size_t>(s)];
      const long b = s + 1 < m ? static_cast<long>(c.keep[static_cast<std::size_t>(s + 1)]) : c.keep[0] + n;
      const bool last_point_too = !c.periodic && s + 1 == segments;
      for (long j = a; j < b || (j == b && last_point_too); ++j) {
        const Vec3 p = ps.point(c.uv[static_cast<std::size_t>(j % n)]);
        double d2 = norm2(p - line.front());
        for (std::size_t i = 0; i + 1 < line.size(); ++i) {
          const Vec3 ab = line[i + 1] - line[i];
          const double l2 = norm2(ab);
          double t = l2 > 0 ? dot(p - line[i], ab) / l2 : 0.0;
          t = std::clamp(t, 0.0, 1.0);
          d2 = std::min(d2, norm2(p - (line[i] + t * ab)));
        }
        CHECK(got[static_cast<std::size_t>(j % n)] == std::sqrt(d2));
        ++checked;
      }
    }
    CHECK(checked >= c.full.size());
  }
}
