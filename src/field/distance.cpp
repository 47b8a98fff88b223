// Distance field: chord distance to the nearest sample point of the listed
// points and curves (paper section 3.1's shore proximity function f3).
#include "field/distance.h"

#include <cmath>

#include <fmt/format.h>

#include "field/bounded_field.h"
#include "field/error.h"
#include "field/kinds.h"
#include "field/knn.h"

namespace sm::field {
namespace {

class DistanceField final : public SizeField, public BoundedEval {
 public:
  DistanceField(std::vector<Vec3> samples, KnnOptions opts) : tree_(std::move(samples), opts) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override { tree_.nearest(pts, h); }
  // Beyond the limit the search stops: a far point costs one descent of the tree.
  void eval_below(std::span<const Vec3> pts, std::span<const double> limit, std::span<double> h) const override {
    tree_.nearest_below(pts, limit, h);
  }

 private:
  KdTree tree_;
};

// A listed point or curve that does not exist: Gmsh's Distance skips it (Mesh/Field.cpp).
void skip_missing(const BuildInputs& in, std::string_view option, std::string_view what, int tag) {
  if (!in.ctx.compat_note) in.bad(option, fmt::format("{} {} does not exist", what, tag));
  in.ctx.compat_note(in.id, option, what, tag);
}

FieldPtr make_distance(const BuildInputs& in) {
  const Options& o = in.opts;
  std::vector<Vec3> samples;
  for (double v : o.list("PointsList")) {
    const int tag = static_cast<int>(v);
    std::optional<Vec3> p;
    if (in.ctx.point_position) p = in.ctx.point_position(tag);
    if (p)
      samples.push_back(*p);
    else
      skip_missing(in, "PointsList", "Point", tag);
  }
  const int n = static_cast<int>(o.number("NumPointsPerCurve"));
  if (n < 1 && !o.list("CurvesList").empty()) in.bad("NumPointsPerCurve", "must be at least 1");
  for (double v : o.list("CurvesList")) {
    const int tag = static_cast<int>(v);
    std::optional<std::vector<Vec3>> s;
    if (in.ctx.curve_samples) s = in.ctx.curve_samples(tag, n);
    if (s)
      samples.insert(samples.end(), s->begin(), s->end());
    else
      skip_missing(in, "CurvesList", "Curve", tag);
  }
  for (double v : o.list("SurfacesList")) {
    const int tag = static_cast<int>(v);
    std::optional<std::vector<Vec3>> s;
    if (in.ctx.surface_samples) s = in.ctx.surface_samples(tag, n);
    if (!s) in.bad("SurfacesList", fmt::format("Surface {} does not exist or cannot be sampled", tag));
    samples.insert(samples.end(), s->begin(), s->end());
  }
  return make_distance_field(std::move(samples));
}

}  // namespace

FieldPtr make_distance_field(std::vector<Vec3> samples) {
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Vec3& p = samples[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      FieldError e(FieldErrc::BadValue, fmt::format("Distance: sample point {} is not finite", i));
      e.bad = BadValueWhat::DistanceSample;
      e.value = static_cast<double>(i);
      throw e;
    }
  }
  return std::make_shared<DistanceField>(std::move(samples), KnnOptions{});
}

KindSpec distance_kind() {
  return {"Distance",
          "Chord (3D Euclidean) distance to the nearest sample point: the listed points, "
          "NumPointsPerCurve samples per listed curve (end points excluded, as Gmsh), and "
          "surface point clouds. Exact nearest neighbour by a k-d tree.",
          {
              list_opt("PointsList", "point tags", {"NodesList"}),
              list_opt("CurvesList", "curve tags", {"EdgesList"}),
              list_opt("SurfacesList", "surface tags", {"FacesList"}),
              num_opt("NumPointsPerCurve", 20, "samples per curve (Sampling in Gmsh >= 4.9)",
                      {"Sampling", "NNodesByEdge"}),
              num_opt("FieldX", -1, "ignored (deprecated in Gmsh)"),
              num_opt("FieldY", -1, "ignored (deprecated in Gmsh)"),
              num_opt("FieldZ", -1, "ignored (deprecated in Gmsh)"),
          },
          make_distance};
}

}  // namespace sm::field
