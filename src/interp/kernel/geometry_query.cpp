// Expressions that read or change the model: Point{t} coordinates, Curve{:} tags,
// Physical groups, In BoundingBox, Boundary/CombinedBoundary/PointsOf, and the
// Translate/Rotate/Symmetry/Dilate/Duplicata transforms with their shape blocks.
#include <algorithm>
#include <array>
#include <cstdlib>

#include <fmt/format.h>

#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/interpreter.h"
#include "interp/provenance.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// Entities of physical groups `tags` of dimension dim, as positive tags (the sign stored for
// MSH 2 orientation is not listed, as in Gmsh). An unknown group gives nothing (Gmsh 4.8.4:
// `#Physical Curve{7}[]` is 0).
std::vector<int> physical_members(const geo::Model& m, int dim, const std::vector<int>& tags) {
  std::vector<int> out;
  for (int t : tags)
    for (int e : m.physical_entities(dim, t)) out.push_back(e);
  return out;
}

// The groups of dimension dim with an existing member (`Physical Curve{:}`: a group whose
// entities were all deleted is not listed, gmsh 4.8.4).
std::vector<int> live_groups(const geo::Model& m, int dim) {
  std::vector<int> out;
  for (const auto& [key, g] : m.physicals())
    if (key.first == dim && !m.physical_entities(dim, key.second).empty()) out.push_back(key.second);
  return out;
}

std::vector<double> numbers_of(Interpreter& in, const ExprList& items) {
  std::vector<double> out;
  for (ExprId e : items) {
    const std::vector<double> v = in.eval_numbers(e);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

std::vector<double> sized(Interpreter& in, SourceRange at, std::vector<double> v, std::size_t n, const char* what) {
  if (v.size() != n && n == 1) in.fail(at, Diag::ListNeedsOneNumber, what, v.size());
  if (v.size() != n) in.fail(at, Diag::ListNeedsNumbers, what, n, v.size());
  return v;
}

Vec3 vec3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// Geometry.CopyMeshingMethod 1: a copy made by Duplicata meshes as its source does, as in
// Gmsh 4.8.4's CopyCurve/CopySurface: a curve's transfinite law, a surface's transfinite
// flag, recombination and algorithm. Explicit transfinite corners are not copied (they
// name the source's points): the copy takes its corners from its boundary, and Gmsh warns.
void copy_meshing_method(Interpreter& in, SourceRange at, const std::vector<std::array<int, 3>>& copied) {
  MeshConstraints& c = in.kernel().constraints;
  bool dropped_corners = false;
  for (const auto& [dim, from, to] : copied) {
    if (dim == 1) {
      if (const auto it = c.curves.find(from); it != c.curves.end()) c.curves[to] = it->second;
      continue;
    }
    if (const auto it = c.surfaces.find(from); it != c.surfaces.end()) {
      TransfiniteSurfaceSpec spec = it->second;
      dropped_corners = dropped_corners || !spec.corners.empty();
      spec.corners.clear();
      c.surfaces[to] = spec;
    }
    if (c.recombine.count(from)) c.recombine.insert(to);
    if (const auto it = c.surface_algorithm.find(from); it != c.surface_algorithm.end())
      c.surface_algorithm[to] = it->second;
  }
  if (dropped_corners)
    in.diags().report(at, Diag::GmshCompatTransfiniteCopy);
}

std::vector<geo::DimTag> apply_transform(Interpreter& in, const Expr& x, const TransformExpr& t) {
  geo::Model& m = in.kernel().model;
  if (t.kind == TransformKind::Extrude) return apply_extrude(in, x, t);
  const SourceRange at = x.range;
  // The parameters first, as Gmsh's parser reduces them before the shapes.
  std::vector<std::vector<double>> p;
  for (ExprId e : t.params) p.push_back(in.eval_numbers(e));
  std::vector<geo::DimTag> ents = eval_shape_block(in, t.shapes, false);
  sync_geometry_options(in);
  geo::GeoStatus st;
  switch (t.kind) {
    case TransformKind::Translate:
      st = m.translate(ents, vec3(sized(in, at, numbers_of(in, t.params), 3, "Translate{dx, dy, dz}")));
      break;
    case TransformKind::Rotate: {
      if (p.size() != 3)
        in.fail(at, Diag::ListRotateParameters);
      const Vec3 axis = vec3(sized(in, at, p[0], 3, "the Rotate axis"));
      const Vec3 point = vec3(sized(in, at, p[1], 3, "the Rotate point"));
      st = m.rotate(ents, axis, point, sized(in, at, p[2], 1, "the Rotate angle")[0]);
      break;
    }
    case TransformKind::Symmetry: {
      const std::vector<double> a = sized(in, at, numbers_of(in, t.params), 4, "Symmetry{a, b, c, d}");
      st = m.symmetry(ents, a[0], a[1], a[2], a[3]);
      break;
    }
    case TransformKind::Dilate: {
      if (p.size() != 2) in.fail(at, Diag::ListDilateParameters);
      const Vec3 c = vec3(sized(in, at, p[0], 3, "the Dilate centre"));
      if (p[1].size() != 1 && p[1].size() != 3)
        in.fail(at, Diag::ListDilateFactor, p[1].size());
      const Vec3 f = p[1].size() == 1 ? Vec3{p[1][0], p[1][0], p[1][0]} : vec3(p[1]);
      st = m.dilate(ents, c, f);
      break;
    }
    case TransformKind::Extrude: break;   // above
    case TransformKind::Duplicata: {
      std::vector<std::array<int, 3>> copied;
      auto r = m.duplicate(ents, &copied);
      report_compat_notes(in, at);
      if (!r) fail_geo(in, at, r.error());
      if (in.options().number("Geometry.CopyMeshingMethod") != 0) copy_meshing_method(in, at, copied);
      for (const geo::DimTag& d : *r) record_created(in.kernel(), d.dim, std::abs(d.tag), at);
      return std::move(*r);
    }
  }
  if (!st) fail_geo(in, at, st.error());
  return ents;
}

std::vector<geo::DimTag> eval_boundary(Interpreter& in, const Expr& x, const BoundaryExpr& b) {
  const geo::Model& m = in.kernel().model;
  std::vector<geo::DimTag> ents = eval_shape_block(in, b.shapes, true);
  if (b.kind != BoundaryKind::PointsOf) {
    auto r = m.boundary(ents, b.kind == BoundaryKind::CombinedBoundary);
    if (!r) fail_geo(in, x.range, r.error());
    return std::move(*r);
  }
  // PointsOf, as gmsh 4.8.4 prints it: a point is itself, a curve gives its begin and end
  // points (end first for -c), a surface the points of its boundary, each once, in the
  // order first reached; nothing is merged across the listed entities.
  std::vector<geo::DimTag> points;
  for (const geo::DimTag& d : ents) {
    if (d.dim == 0) {
      points.push_back({0, std::abs(d.tag)});
      continue;
    }
    auto r = m.boundary({d}, false);
    if (!r) fail_geo(in, x.range, r.error());
    if (d.dim == 1) {
      for (const geo::DimTag& p : *r) points.push_back({0, std::abs(p.tag)});
      continue;
    }
    std::vector<geo::DimTag> mine;
    auto below = m.boundary(*r, false);
    if (!below) fail_geo(in, x.range, below.error());
    for (const geo::DimTag& p : *below) {
      const geo::DimTag q{0, std::abs(p.tag)};
      if (std::find(mine.begin(), mine.end(), q) == mine.end()) mine.push_back(q);
    }
    points.insert(points.end(), mine.begin(), mine.end());
  }
  return points;
}

Value tag_list(const std::vector<geo::DimTag>& ents) {
  std::vector<double> out;
  out.reserve(ents.size());
  for (const geo::DimTag& d : ents) out.push_back(d.tag);
  return Value::list(std::move(out));
}

Value eval_entity_query(Interpreter& in, const Expr& x, const EntityQueryExpr& q) {
  const geo::Model& m = in.kernel().model;
  const int dim = static_cast<int>(q.ent);
  std::vector<double> out;
  if (q.physical) {
    std::vector<int> groups;
    if (q.all) {   // `Physical Curve{:}`: the group tags themselves (gmsh 4.8.4)
      for (int t : live_groups(m, dim)) out.push_back(t);
      return Value::list(std::move(out));
    } else {
      for (ExprId e : q.tags) {
        const std::vector<int> t = eval_tags(in, e);
        groups.insert(groups.end(), t.begin(), t.end());
      }
    }
    for (int e : physical_members(m, dim, groups)) out.push_back(e);
    return Value::list(std::move(out));
  }
  if (q.all) {
    for (int t : m.tags(dim)) out.push_back(t);
    return Value::list(std::move(out));
  }
  if (q.ent != EntityKind::Point)
    in.fail(x.range, Diag::EntityQueryNoValue, entity_name(q.ent));
  for (ExprId e : q.tags) {
    for (int t : eval_tags(in, e)) {
      const geo::ModelVertex* v = m.vertex(t);
      if (!v)
        in.fail(x.range, Diag::GeoUnknownQueriedPoint, t);
      out.insert(out.end(), {v->xyz.x, v->xyz.y, v->xyz.z});
    }
  }
  return Value::list(std::move(out));
}

}  // namespace

std::vector<geo::DimTag> eval_shape_block(Interpreter& in, const ShapeBlock& block, bool keep_sign) {
  std::vector<geo::DimTag> out;
  for (const ShapeItem& item : block) {
    switch (item.kind) {
      case ShapeItem::Kind::Entities: {
        const geo::Model& m = in.kernel().model;
        const int dim = static_cast<int>(item.ent);
        std::vector<int> tags;
        if (item.all && item.physical) {   // `Physical Curve{:};`: every group's members
          tags = live_groups(m, dim);
        } else if (item.all) {
          tags = m.tags(dim);
        } else {
          for (ExprId e : item.tags) {
            const std::vector<int> t = eval_tags(in, e);
            tags.insert(tags.end(), t.begin(), t.end());
          }
        }
        if (item.physical) tags = physical_members(m, dim, tags);
        for (int t : tags) out.push_back({dim, keep_sign ? t : std::abs(t)});
        break;
      }
      case ShapeItem::Kind::Create:
        if (auto made = create_geometry(in, item.create)) out.push_back(*made);
        break;
      case ShapeItem::Kind::Nested: {
        const std::vector<geo::DimTag> inner = eval_shape_expr(in, item.nested);
        out.insert(out.end(), inner.begin(), inner.end());
        break;
      }
    }
  }
  return out;
}

std::vector<geo::DimTag> eval_shape_expr(Interpreter& in, ExprId e) {
  const Expr& x = in.ast().expr(e);
  if (const auto* t = std::get_if<TransformExpr>(&x.node)) return apply_transform(in, x, *t);
  if (const auto* b = std::get_if<BoundaryExpr>(&x.node)) return eval_boundary(in, x, *b);
  in.fail(x.range, Diag::TypeExpectedShape);
}

bool physical_group_name(Interpreter& in, ExprId e, std::string& out) {
  const auto* q = std::get_if<EntityQueryExpr>(&in.ast().expr(e).node);
  if (!q || !q->physical || q->all || q->tags.size() != 1) return false;
  const geo::PhysicalGroup* g = in.kernel().model.physical(static_cast<int>(q->ent), eval_tag(in, q->tags[0]));
  out = g ? g->name : "";
  return true;
}

// Intersect Curve{..} Surface{s}: one new point (tag newp) per curve that meets the
// surface, at the curve's point, sized as Gmsh sizes it (the end points' sizes interpolated
// along the curve's parameter); a curve that misses it adds nothing, as in Gmsh.
static Value eval_intersect(Interpreter& in, const Expr& x, const IntersectExpr& q) {
  std::vector<int> curves;
  for (ExprId c : q.curves)
    for (int t : eval_tags(in, c)) curves.push_back(t);
  const int surface = eval_tag(in, q.surface);
  geo::Model& m = in.kernel().model;
  std::vector<double> out;
  for (int c : curves) {
    auto r = m.intersect_curve_surface(c, surface);
    if (!r) fail_geo(in, x.range, r.error());
    if (!*r) continue;
    const double t = **r;
    const geo::ModelCurve& mc = *m.curve(c);
    const geo::ModelVertex& b = *m.vertex(mc.begin);
    const geo::ModelVertex& e = *m.vertex(mc.end);
    const double lc = b.lc < geo::kMaxLc && e.lc < geo::kMaxLc ? (1 - t) * b.lc + t * e.lc : 0.0;
    const int tag = m.new_point_tag();
    sync_geometry_options(in);
    if (auto st = m.add_point(tag, mc.shape->point(t), lc); !st) fail_geo(in, x.range, st.error());
    record_created(in.kernel(), 0, tag, x.range);
    out.push_back(tag);
  }
  return Value::list(std::move(out));
}

Value eval_model_expr(Interpreter& in, ExprId e) {
  const Expr& x = in.ast().expr(e);
  switch (x.kind()) {
    case ExprKind::EntityQuery: return eval_entity_query(in, x, std::get<EntityQueryExpr>(x.node));
    case ExprKind::EntityInBox: {
      const auto& q = std::get<EntityInBoxExpr>(x.node);
      const std::vector<double> b =
          sized(in, x.range, numbers_of(in, q.box), 6, "In BoundingBox{xmin, ymin, zmin, xmax, ymax, zmax}");
      std::vector<double> out;
      const int dim = static_cast<int>(q.ent);
      if (dim <= 2)
        for (int t : in.kernel().model.in_bounding_box(dim, {b[0], b[1], b[2]}, {b[3], b[4], b[5]})) out.push_back(t);
      return Value::list(std::move(out));
    }
    case ExprKind::Boundary:
    case ExprKind::Transform: return tag_list(eval_shape_expr(in, e));
    case ExprKind::CoastlineQuery: return eval_coastline_query(in, e);
    case ExprKind::Intersect: return eval_intersect(in, x, std::get<IntersectExpr>(x.node));
    default: break;
  }
  in.not_supported_expr(e, in.text_of(x.range).substr(0, 30));
}

}  // namespace sm::interp
