// LonLat field: Field[InField](lon, lat, 0) in radians, with Gmsh 4.8.4's
// quirks (docs/fields.md): the latitude uses RadiusStereo, not |X|.
#include <cmath>
#include <vector>

#include "field/kinds.h"

namespace sm::field {
namespace {

class LonLatField final : public CompositeField {
 public:
  LonLatField(FieldPtr in, bool from_stereo, double r)
      : in_(std::move(in)), from_stereo_(from_stereo), r_(r) {}

 protected:
  void run(const EntityRef* on, std::span<const Vec3> pts, std::span<double> h) const override {
    std::vector<Vec3> ll(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double x = pts[i].x, y = pts[i].y, z = pts[i].z;
      if (from_stereo_) {
        // (x, y) are "2R" stereographic coordinates (projection from the
        // south pole onto the tangent plane at the north pole); z is ignored.
        const double r4 = 4 * r_ * r_;
        const double d = r4 + x * x + y * y;
        const double xi = x, eta = y;
        x = r4 * xi / d;
        y = r4 * eta / d;
        z = r_ * (r4 - xi * xi - eta * eta) / d;
      }
      ll[i] = {std::atan2(y, x), std::asin(z / r_), 0.0};
    }
    eval_input(*in_, on, ll, h);
  }

 private:
  FieldPtr in_;
  bool from_stereo_;
  double r_;
};

FieldPtr make_lonlat(const BuildInputs& in) {
  const double r = in.opts.number("RadiusStereo");
  if (!(r > 0) || !std::isfinite(r)) in.bad("RadiusStereo", "must be a positive radius");
  return std::make_shared<LonLatField>(in.input("InField"), in.opts.number("FromStereo") != 0, r);
}

}  // namespace

KindSpec lonlat_kind() {
  return {"LonLat",
          "Field[InField](atan2(y,x), asin(z/RadiusStereo), 0): longitude and latitude in "
          "radians. Set RadiusStereo to the sphere radius (1 for a unit PolarSphere).",
          {
              field_opt("InField", 1, "field evaluated at (lon, lat, 0)", {"IField"}),
              num_opt("FromStereo", 0,
                      "1: x, y are 2R stereographic coordinates of a flat mesh (z ignored)"),
              num_opt("RadiusStereo", 6371e3,
                      "sphere radius used for the latitude (and the stereographic map)"),
          },
          make_lonlat};
}

}  // namespace sm::field
