// Gradation field: Field[InField] sampled on a lon/lat background grid,
// limited to |grad h| <= Rate by a fast march, then interpolated bilinearly.
#include "field/gradation.h"

#include <cmath>
#include <cstdint>
#include <queue>

#include <fmt/format.h>

#include "field/error.h"
#include "field/kinds.h"

namespace sm::field {

void limit_gradation(LonLatGrid& g, double rate, double radius) {
  const int nx = g.nlon, ny = g.nlat;
  std::vector<Vec3> pos(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      pos[static_cast<std::size_t>(j) * nx + i] = point_of(g.lon(i), g.lat(j), radius);
  // Heap of (value, node); equal values pop by node index, so the march is
  // deterministic. Stale entries (value above the node's current one) are
  // skipped.
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  for (std::size_t k = 0; k < g.v.size(); ++k) heap.emplace(g.v[k], static_cast<std::uint32_t>(k));
  std::vector<char> done(g.v.size(), 0);
  while (!heap.empty()) {
    const auto [hu, u] = heap.top();
    heap.pop();
    if (done[u] || hu > g.v[u]) continue;
    done[u] = 1;
    const int iu = static_cast<int>(u % static_cast<std::uint32_t>(nx));
    const int ju = static_cast<int>(u / static_cast<std::uint32_t>(nx));
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if (!di && !dj) continue;
        const int jv = ju + dj;
        if (jv < 0 || jv >= ny) continue;
        int iv = iu + di;
        if (g.period) {
          // Columns past the period repeat earlier ones: step through the
          // wrapped grid, and keep duplicate columns in sync below.
          iv = g.wrap(iv);
        } else if (iv < 0 || iv >= nx) {
          continue;
        }
        const std::size_t v = static_cast<std::size_t>(jv) * nx + iv;
        if (done[v]) continue;
        const double cand = hu + rate * norm(pos[u] - pos[v]);
        if (cand < g.v[v]) {
          g.v[v] = cand;
          heap.emplace(cand, static_cast<std::uint32_t>(v));
        }
      }
  }
  if (g.period)
    for (int j = 0; j < ny; ++j)
      for (int i = g.period; i < nx; ++i) g.at(i, j) = g.at(g.wrap(i), j);
}

namespace {

class GradationField final : public SizeField {
 public:
  GradationField(LonLatGrid g, double radius) : g_(std::move(g)), radius_(radius) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double lon, lat;
      lonlat_of(pts[i], radius_, lon, lat);
      h[i] = g_.interp(lon, lat);
    }
  }

 private:
  LonLatGrid g_;
  double radius_;
};

FieldPtr make_gradation(const BuildInputs& in) {
  const Options& o = in.opts;
  const double rate = o.number("Rate"), radius = o.number("Radius"), res = o.number("Resolution");
  if (!(rate > 0) || !std::isfinite(rate)) in.bad("Rate", "must be a positive slope");
  if (!(radius > 0) || !std::isfinite(radius)) in.bad("Radius", "must be a positive sphere radius");
  if (!(res > 0) || res > 90) in.bad("Resolution", "must be in (0, 90] degrees");
  const double lon_min = o.number("LonMin"), lon_max = o.number("LonMax");
  const double lat_min = o.number("LatMin"), lat_max = o.number("LatMax");
  if (!(lon_max > lon_min) || lon_max - lon_min > 360) in.bad("LonMax", "need LonMin < LonMax <= LonMin + 360");
  if (!(lat_max > lat_min) || lat_min < -90 || lat_max > 90) in.bad("LatMax", "need -90 <= LatMin < LatMax <= 90");
  LonLatGrid g;
  g.nlon = static_cast<int>(std::ceil((lon_max - lon_min) / res - 1e-9)) + 1;
  g.nlat = static_cast<int>(std::ceil((lat_max - lat_min) / res - 1e-9)) + 1;
  if (static_cast<double>(g.nlon) * g.nlat > 5e7) in.bad("Resolution", "grid would exceed 5e7 nodes");
  g.lon0 = lon_min;
  g.lat0 = lat_min;
  g.dlon = (lon_max - lon_min) / (g.nlon - 1);
  g.dlat = (lat_max - lat_min) / (g.nlat - 1);
  g.detect_wrap();
  std::vector<Vec3> pts(static_cast<std::size_t>(g.nlon) * g.nlat);
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i)
      pts[static_cast<std::size_t>(j) * g.nlon + i] = point_of(g.lon(i), g.lat(j), radius);
  g.v.resize(pts.size());
  in.input("InField")->eval(pts, g.v);
  for (int j = 0; j < g.nlat; ++j)
    for (int i = 0; i < g.nlon; ++i) {
      const double v = g.at(i, j);
      if (!(v > 0))
        in.bad("InField", fmt::format("input size {} at lon {}, lat {} is not positive", v,
                                      g.lon(i), g.lat(j)));
    }
  limit_gradation(g, rate, radius);
  return std::make_shared<GradationField>(std::move(g), radius);
}

}  // namespace

KindSpec gradation_kind() {
  return {"Gradation",
          "Field[InField] with its growth limited to |grad h| <= Rate on the sphere: sampled on "
          "a lon/lat grid of step Resolution (degrees), lowered by a fast march from the "
          "smallest sizes (h(v) = min_u h(u) + Rate*d(u,v)), then interpolated bilinearly.",
          {
              field_opt("InField", 1, "size field to limit", {"IField"}),
              num_opt("Rate", 0.2, "largest allowed size increase per unit length"),
              num_opt("Radius", 1, "radius of the sphere the points lie on (1: unit PolarSphere)"),
              num_opt("Resolution", 0.25, "background grid step in degrees"),
              num_opt("LonMin", -180, "west edge of the background grid (degrees)"),
              num_opt("LonMax", 180, "east edge (LonMax - LonMin = 360 wraps round the globe)"),
              num_opt("LatMin", -90, "south edge (degrees)"),
              num_opt("LatMax", 90, "north edge (degrees)"),
          },
          make_gradation};
}

}  // namespace sm::field
