// `Extrude {...} {shapes; Layers{...}; Recombine;}` (docs/interpreter.md): the parameters
// told apart as Gmsh's grammar tells them (Parser/Gmsh.y: {dx,dy,dz} a translation,
// {{axis},{point},angle} a rotation, {{dx,dy,dz},{axis},{point},angle} a twist), the mesh
// parameters checked, then geo::Model::extrude (geo/extrude.cpp). The result is Gmsh's list.
#include <cmath>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/provenance.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// Above this many elements along one extrusion the structured mesh is refused (a typo
// such as Layers{1e9} would otherwise ask for a billion layers).
constexpr double kMaxLayerElements = 1e6;

Vec3 vec3_of(Interpreter& in, SourceRange at, const std::vector<double>& v, const char* what) {
  if (v.size() != 3)
    in.fail(at, Diag::ListNeedsNumbers, what, std::size_t{3}, v.size());
  return {v[0], v[1], v[2]};
}

double angle_of(Interpreter& in, SourceRange at, const std::vector<double>& v) {
  if (v.size() != 1)
    in.fail(at, Diag::ListNeedsOneNumber, std::string_view("the extrusion's angle"), v.size());
  if (!std::isfinite(v[0])) in.fail(at, Diag::ExtrudeAngleNotFinite);
  return v[0];
}

void read_layers(Interpreter& in, const ExtrudeMeshParams& mp, geo::ExtrudeSpec& spec) {
  if (mp.layers.empty()) return;
  const SourceRange at = mp.layers_range;
  std::vector<std::vector<double>> items;
  for (ExprId e : mp.layers) items.push_back(in.eval_numbers(e));
  double total = 0;
  if (items.size() == 1 && items[0].size() == 1) {
    const double n = std::fabs(items[0][0]);
    if (!std::isfinite(n) || n >= kMaxLayerElements)
      in.fail(at, Diag::LayersElementCount, items[0][0], kMaxLayerElements);
    if (static_cast<int>(n) == 0) return;   // Gmsh accepts 0 to switch the layers off
    spec.layered = true;
    spec.layers.elements = {static_cast<int>(n)};
    spec.layers.heights = {1.0};
    return;
  }
  if (items.size() != 2 || items[0].size() != items[1].size() || items[0].empty())
    in.fail(at, Diag::ListLayers);
  double prev = 0;
  for (std::size_t i = 0; i < items[0].size(); ++i) {
    const double d = items[0][i], h = items[1][i];
    if (!std::isfinite(d) || !std::isfinite(h))
      in.fail(at, Diag::LayersNotFinite);
    const int n = d > 0 ? static_cast<int>(std::min(d, kMaxLayerElements)) : 1;   // Gmsh: d > 0 ? (int)d : 1
    total += n;
    if (total >= kMaxLayerElements)
      in.fail(at, Diag::LayersTotalElements, kMaxLayerElements);
    if (!(h > prev))
      in.fail(at, Diag::LayersHeightsNotIncreasing, i + 1, h, prev);
    prev = h;
    spec.layers.elements.push_back(n);
    spec.layers.heights.push_back(h);
  }
  spec.layered = true;
}

}  // namespace

std::vector<geo::DimTag> apply_extrude(Interpreter& in, const Expr& x, const TransformExpr& t) {
  const SourceRange at = x.range;
  std::vector<std::vector<double>> p;
  for (ExprId e : t.params) p.push_back(in.eval_numbers(e));
  geo::ExtrudeSpec spec;
  if (p.size() == 4) {
    spec.kind = geo::ExtrudeKind::Twist;
    spec.translation = vec3_of(in, at, p[0], "the twist's translation");
    spec.axis = vec3_of(in, at, p[1], "the twist's axis");
    spec.point = vec3_of(in, at, p[2], "the twist's axis point");
    spec.angle = angle_of(in, at, p[3]);
  } else if (p.size() == 3 && p[0].size() == 3) {
    spec.kind = geo::ExtrudeKind::Rotate;
    spec.axis = vec3_of(in, at, p[0], "the rotation's axis");
    spec.point = vec3_of(in, at, p[1], "the rotation's axis point");
    spec.angle = angle_of(in, at, p[2]);
  } else {
    std::vector<double> all;
    for (const auto& v : p) all.insert(all.end(), v.begin(), v.end());
    if (all.size() != 3)
      in.fail(at, Diag::ListExtrudeParameters, all.size());
    spec.translation = {all[0], all[1], all[2]};
  }
  for (double v : {spec.translation.x, spec.translation.y, spec.translation.z, spec.axis.x, spec.axis.y, spec.axis.z,
                   spec.point.x, spec.point.y, spec.point.z})
    if (!std::isfinite(v)) in.fail(at, Diag::ExtrudeParametersNotFinite);
  if (spec.kind != geo::ExtrudeKind::Translate && !(norm(spec.axis) > 0))
    in.fail(at, Diag::ExtrudeAxisZero);
  std::vector<geo::DimTag> ents = eval_shape_block(in, t.shapes, true);
  read_layers(in, t.extrude, spec);
  if (t.extrude.has_recombine) spec.recombine = in.eval_number(t.extrude.recombine) != 0;
  const double sp = in.options().number("Geometry.ExtrudeSplinePoints");
  spec.spline_points = sp >= 1 && sp < 1e4 ? static_cast<int>(sp) : 1;
  spec.return_lateral = in.options().number("Geometry.ExtrudeReturnLateralEntities") != 0;
  sync_geometry_options(in);
  geo::Model& m = in.kernel().model;
  auto r = m.extrude(ents, spec);
  report_compat_notes(in, at);
  if (!r) fail_geo(in, at, r.error());
  for (const geo::DimTag& d : *r)
    if (in.kernel().created_at.count({d.dim, std::abs(d.tag)}) == 0)
      record_created(in.kernel(), d.dim, std::abs(d.tag), at);
  return std::move(*r);
}

void embed_in_volume(Interpreter& in, const Stmt& s, const EmbedStmt& n) {
  const geo::Model& m = in.kernel().model;
  const int v = eval_tag(in, n.target_tag);
  if (!m.volumes().count(v))
    in.fail(s.range, Diag::GeoUnknownEmbeddingVolume, v);
  const int dim = static_cast<int>(n.ent);
  for (int t : eval_tags(in, n.tags)) {
    const int a = std::abs(t);
    const bool ok = (dim == 0 && m.vertex(a)) || (dim == 1 && m.curve(a)) || (dim == 2 && m.surface(a));
    if (!ok)
      in.fail(s.range, Diag::GeoUnknownToEmbedIn, std::string(entity_name(n.ent)), a, v);
  }
  // Gmsh embeds them in the volume's 3D mesh only: a 2D mesh is the same without them.
}

}  // namespace sm::interp
