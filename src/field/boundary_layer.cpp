// BoundaryLayer: Gmsh 4.8.4's BoundaryLayer field (Mesh/Field.cpp), its options and
// checks, its scalar size, and the growth of its layers (field/boundary_layer.h).
#include "field/boundary_layer.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "field/error.h"
#include "field/kinds.h"
#include "field/knn.h"

namespace sm::field {

bool BoundaryLayerParams::has_curve(int tag) const {
  return std::find(curves.begin(), curves.end(), tag) != curves.end();
}
bool BoundaryLayerParams::is_fan_point(int tag) const {
  return std::find(fan_points.begin(), fan_points.end(), tag) != fan_points.end();
}
bool BoundaryLayerParams::is_end_point(int tag) const {
  return std::find(end_points.begin(), end_points.end(), tag) != end_points.end();
}
bool BoundaryLayerParams::excludes(int surface) const {
  return std::find(excluded_surfaces.begin(), excluded_surfaces.end(), surface) != excluded_surfaces.end();
}
int BoundaryLayerParams::fan_size(int tag, int default_elements) const {
  if (fan_sizes.size() != fan_points.size()) return default_elements;
  for (std::size_t i = 0; i < fan_points.size(); ++i)
    if (fan_points[i] == tag) return fan_sizes[i];
  return 0;
}
double BoundaryLayerParams::size_at_point(int tag) const {
  for (const auto& [point, h] : point_sizes)
    if (point == tag) return h;
  return size;
}

std::vector<double> layer_distances(const BoundaryLayerParams& p, double first, double limit) {
  std::vector<double> out;
  if (!(first > 0) || !std::isfinite(first)) return out;
  if (p.beta_law) {
    // Gmsh's beta law: t_i = 1 + beta (1 - e_i) / (1 + e_i), e_i = ((1 + beta) / (beta - 1))^(1 - eta_i),
    // eta_i = (i + 1) / NbLayers; the column's points at first * t_i / t_0.
    const int n = std::clamp(p.nb_layers, 0, kMaxBoundaryLayers);
    const double zlog = std::log((1 + p.beta) / (p.beta - 1));
    std::vector<double> t(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double eta = static_cast<double>(i + 1) / n;
      const double power = std::exp(zlog * (1 - eta));
      t[static_cast<std::size_t>(i)] = 1 + p.beta * (1 - power) / (1 + power);
    }
    for (int i = 0; i < n; ++i) out.push_back(first * t[static_cast<std::size_t>(i)] / t[0]);
    return out;
  }
  double L = first;
  double step = first;
  while (L <= limit && static_cast<int>(out.size()) < kMaxBoundaryLayers) {
    out.push_back(L);
    step *= p.ratio;
    L += step;
  }
  return out;
}

namespace {

// Gmsh's scalar value: with d the distance to the listed points and curves,
// min(SizeFar, d (Ratio - 1) + Size) up to d = Thickness * Ratio, no constraint beyond.
class BoundaryLayerField final : public SizeField {
 public:
  BoundaryLayerField(std::vector<Vec3> samples, const BoundaryLayerParams& p)
      : empty_(samples.empty()), tree_(std::move(samples), KnnOptions{}), size_(p.size), far_(p.size_far),
        ratio_(p.ratio), thickness_(p.thickness) {}

  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    if (empty_) {
      std::fill(h.begin(), h.end(), kMaxLc);
      return;
    }
    tree_.nearest(pts, h);
    for (double& v : h) {
      const double d = v;
      v = d > thickness_ * ratio_ ? kMaxLc : std::min(far_, d * (ratio_ - 1) + size_);
    }
  }

 private:
  bool empty_;
  KdTree tree_;
  double size_, far_, ratio_, thickness_;
};

[[noreturn]] void bad(int id, std::string_view option, const std::string& why) {
  FieldError e(FieldErrc::BadValue, fmt::format("Field[{}] (BoundaryLayer): option '{}': {}", id, option, why));
  e.field_id = id;
  e.option = std::string(option);
  e.name = "BoundaryLayer";
  e.reason = why;
  throw e;
}

void positive(int id, std::string_view option, double v) {
  if (!(v > 0) || !std::isfinite(v)) bad(id, option, fmt::format("must be positive and finite, not {:g}", v));
}

std::vector<int> tags(const Options& o, std::string_view option, int id, bool allow_zero = false) {
  std::vector<int> out;
  for (double v : o.list(option)) {
    if (v != std::floor(v) || (allow_zero ? v < 0 : v <= 0))
      bad(id, option, fmt::format("{:g} is not a {} tag", v, allow_zero ? "non-negative" : "positive"));
    out.push_back(static_cast<int>(v));
  }
  return out;
}

// Samples of the listed curves for the scalar value: Gmsh samples each curve densely
// (Mesh/Field.cpp asks 300000 points); 2000 make the distance exact to well under a
// first layer on curves a thousand first layers long. Many curves share 10^6 samples
// (at least 20 each), so that a coastline's thousands of curves stay cheap.
int curve_samples_each(std::size_t curves) {
  if (curves == 0) return 2000;
  return static_cast<int>(std::clamp(1e6 / static_cast<double>(curves), 20.0, 2000.0));
}

FieldPtr make_boundary_layer(const BuildInputs& in) {
  const BoundaryLayerParams p = boundary_layer_params(in.opts, in.id);
  std::vector<Vec3> samples;
  for (int tag : p.end_points) {
    std::optional<Vec3> x;
    if (in.ctx.point_position) x = in.ctx.point_position(tag);
    if (!x) in.bad("PointsList", fmt::format("Point {} does not exist", tag));
    samples.push_back(*x);
  }
  for (int tag : p.fan_points) {
    std::optional<Vec3> x;
    if (in.ctx.point_position) x = in.ctx.point_position(tag);
    if (!x) in.bad("FanPointsList", fmt::format("Point {} does not exist", tag));
  }
  for (const auto& [tag, h] : p.point_sizes) {
    std::optional<Vec3> x;
    if (in.ctx.point_position) x = in.ctx.point_position(tag);
    if (!x) in.bad("SizesList", fmt::format("Point {} does not exist", tag));
  }
  const int each = curve_samples_each(p.curves.size());
  for (int tag : p.curves) {
    std::optional<std::vector<Vec3>> s;
    if (in.ctx.curve_samples) s = in.ctx.curve_samples(tag, each);
    if (!s) in.bad("CurvesList", fmt::format("Curve {} does not exist", tag));
    samples.insert(samples.end(), s->begin(), s->end());
  }
  return std::make_shared<BoundaryLayerField>(std::move(samples), p);
}

}  // namespace

BoundaryLayerParams boundary_layer_params(const Options& o, int id) {
  BoundaryLayerParams p;
  p.curves = tags(o, "CurvesList", id);
  p.end_points = tags(o, "PointsList", id);
  p.fan_points = tags(o, "FanPointsList", id);
  p.excluded_surfaces = tags(o, "ExcludedSurfacesList", id);
  for (double v : o.list("FanPointsSizesList")) {
    if (v != std::floor(v) || v < 0 || v > kMaxBoundaryLayers)
      bad(id, "FanPointsSizesList",
          fmt::format("{:g} is not a count of fan elements (0 to {})", v, kMaxBoundaryLayers));
    p.fan_sizes.push_back(static_cast<int>(v));
  }
  const std::vector<double>& sizes = o.list("SizesList");
  if (sizes.size() % 2 != 0)
    bad(id, "SizesList", fmt::format("takes pairs {{point, size, point, size, ...}}, not {} numbers", sizes.size()));
  for (std::size_t i = 0; i < sizes.size(); i += 2) {
    if (sizes[i] != std::floor(sizes[i]) || sizes[i] <= 0)
      bad(id, "SizesList", fmt::format("{:g} is not a point tag (the list is {{point, size, ...}})", sizes[i]));
    positive(id, "SizesList", sizes[i + 1]);
    p.point_sizes.emplace_back(static_cast<int>(sizes[i]), sizes[i + 1]);
  }
  p.size = o.number("Size");
  p.size_far = o.number("SizeFar");
  p.ratio = o.number("Ratio");
  p.thickness = o.number("Thickness");
  p.aniso_max = o.number("AnisoMax");
  p.quads = o.number("Quads") != 0;
  p.intersect_metrics = o.number("IntersectMetrics") != 0;
  p.beta_law = o.number("BetaLaw") != 0;
  p.beta = o.number("Beta");
  const double nb = o.number("NbLayers");
  positive(id, "Size", p.size);
  positive(id, "SizeFar", p.size_far);
  positive(id, "Thickness", p.thickness);
  positive(id, "AnisoMax", p.aniso_max);
  // A ratio below 1 shrinks the layers: their heights sum to at most Size / (1 - Ratio),
  // so a thicker layer would never end (Gmsh loops for ever there).
  if (!(p.ratio >= 1) || !std::isfinite(p.ratio))
    bad(id, "Ratio", fmt::format("must be at least 1 (each layer at least as high as the one before), not {:g}",
                                 p.ratio));
  if (p.beta_law) {
    if (!(p.beta > 1) || !std::isfinite(p.beta))
      bad(id, "Beta", fmt::format("the beta law needs Beta > 1, not {:g}", p.beta));
    if (nb != std::floor(nb) || nb < 1 || nb > kMaxBoundaryLayers)
      bad(id, "NbLayers", fmt::format("must be a whole number from 1 to {}, not {:g}", kMaxBoundaryLayers, nb));
    p.nb_layers = static_cast<int>(nb);
  } else {
    // The count of layers below Thickness, from Size (1 + r + ... + r^(n-1)) <= Thickness.
    for (const double first : [&] {
           std::vector<double> firsts{p.size};
           for (const auto& ps : p.point_sizes) firsts.push_back(ps.second);
           return firsts;
         }()) {
      const double n = p.ratio > 1 ? std::log1p(p.thickness * (p.ratio - 1) / first) / std::log(p.ratio)
                                   : p.thickness / first;
      if (!(n <= kMaxBoundaryLayers))
        bad(id, "Thickness",
            fmt::format("Thickness {:g} over a first layer of {:g} growing by {:g} makes about {:.3g} layers, more "
                        "than {}: raise Size or Ratio, or lower Thickness",
                        p.thickness, first, p.ratio, n, kMaxBoundaryLayers));
    }
  }
  return p;
}

KindSpec boundary_layer_kind() {
  return {"BoundaryLayer",
          "Layers of elements along the listed curves, for the 2D meshes of the surfaces they bound (active once "
          "named by 'BoundaryLayer Field = n;', Gmsh 4.8.4's 2D boundary layers): the first layer Size high, each "
          "next one Ratio times higher, up to Thickness; a fan of columns at each FanPointsList point; quadrangles "
          "with Quads = 1, else triangles. As a size field: min(SizeFar, d (Ratio - 1) + Size) within Thickness * "
          "Ratio of the curves and points, 1e22 beyond.",
          {
              list_opt("CurvesList", "tags of the curves that get layers", {"EdgesList"}),
              list_opt("PointsList",
                       "tags of points where the layers end: a straight curve leaving such a point (not in "
                       "CurvesList) gets the layer heights as its first 1D nodes",
                       {"NodesList"}),
              list_opt("FanPointsList", "tags of points where a fan of columns turns round the corner",
                       {"FanNodesList"}),
              list_opt("FanPointsSizesList",
                       "elements of the fan per half turn at each FanPointsList point (if not as long as it: "
                       "Mesh.BoundaryLayerFanElements)"),
              num_opt("Size", 0.1, "height of the first layer (normal to the curve)", {"hwall_n"}),
              list_opt("SizesList", "first layer height per point: {point, size, ...} (overrides Size there)",
                       {"hwall_n_nodes"}),
              num_opt("Ratio", 1.1, "height ratio between two successive layers (at least 1)", {"ratio"}),
              num_opt("SizeFar", 1, "element size far from the curves (the scalar value's cap)", {"hfar"}),
              num_opt("Thickness", 0.01, "maximal thickness of the layers", {"thickness"}),
              num_opt("Quads", 0, "1: quadrangles in the layers, 0: each split into two triangles"),
              num_opt("IntersectMetrics", 0, "accepted, as Gmsh (its anisotropic metrics: no effect on the layers)"),
              num_opt("AnisoMax", 1e10, "accepted, as Gmsh (threshold of its anisotropic metrics: no effect here)"),
              num_opt("BetaLaw", 0, "1: NbLayers heights of Gmsh's beta law instead of the Ratio progression"),
              num_opt("Beta", 1.01, "beta of the beta law (> 1)"),
              num_opt("NbLayers", 10, "number of layers of the beta law"),
              list_opt("ExcludedSurfacesList", "tags of surfaces that get no layers", {"ExcludedFaceList"}),
          },
          make_boundary_layer};
}

}  // namespace sm::field
