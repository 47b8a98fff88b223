// Model construction, validation and queries with Gmsh 4.8.4's semantics (tags, loops,
// plane surfaces on a surface geometry, physical groups, Boundary / CombinedBoundary).
#include "geo/model.h"

#include "geo/loop_check.h"
#include "geo/surface_filling.h"


#include <algorithm>
#include <atomic>
#include <limits>
#include <cmath>
#include <initializer_list>

namespace sm::geo {

namespace {

// An unknown entity `tag` of kind `k`, said in the shape `id`; `context` the entities
// the statement was making (for the message, not the provenance notes).
GeoError missing(GeoErrorId id, EntityKind k, int tag, std::vector<int> context = {},
                 std::vector<std::string> words = {}) {
  std::vector<int> tags{tag};
  tags.insert(tags.end(), context.begin(), context.end());
  return make_error(id, k, std::move(tags), {}, {}, std::move(words));
}

}  // namespace

void BoundingBox::add(Vec3 p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

void Model::touch() {
  static std::atomic<std::uint64_t> last{0};
  revision_ = ++last;
}

// ---- tags ----

void Model::bump_max(int slot, int tag) { max_tag_[slot] = std::max(max_tag_[slot], tag); }

// Gmsh lowers the high-water mark by one only when the deleted entity holds it.
void Model::on_delete(int slot, int tag) {
  if (tag == max_tag_[slot]) max_tag_[slot] = tag - 1;
}

int Model::new_reg() const {
  int m = std::max({max_tag_[1], max_tag_[2], max_tag_[3], max_tag_[kLoopSlot], max_tag_[kSurfaceLoopSlot]});
  // Physical tags count as a high-water mark: Gmsh keeps it when groups are emptied or
  // deleted (`Delete Physicals;` leaves newreg and the next auto tag where they were).
  return std::max(m, max_physical_tag_) + 1;
}

int Model::new_curve_tag() const { return options_.old_new_reg ? new_reg() : max_tag_[1] + 1; }
int Model::new_loop_tag() const { return options_.old_new_reg ? new_reg() : max_tag_[kLoopSlot] + 1; }
int Model::new_surface_tag() const { return options_.old_new_reg ? new_reg() : max_tag_[2] + 1; }

void Model::set_max_tag(int dim, int tag) {
  touch();
  const int slot = dim < 0 ? kLoopSlot : std::min(dim, 3);
  max_tag_[slot] = tag;
}

GeoStatus Model::check_new_tag(EntityKind kind, int tag, bool exists) {
  // Gmsh takes tag 0 for points and physical groups (they are never referred to with a
  // sign); a curve, loop or surface 0 could not be reversed as -0, so those stay errors.
  if (tag == 0 && !exists && (kind == EntityKind::Point || kind == EntityKind::Physical)) {
    note_compat(CompatNoteId::TagZero, {}, to_string(kind));
    return {};
  }
  if (tag <= 0) return make_error(GeoErrorId::TagNotPositive, kind, {tag});
  if (exists) return make_error(GeoErrorId::AlreadyExists, kind, {tag});
  return {};
}

// ---- lookups ----

const ModelVertex* Model::vertex(int tag) const {
  auto it = vertices_.find(tag);
  return it == vertices_.end() ? nullptr : &it->second;
}

const ModelCurve* Model::curve(int tag) const {
  auto it = curves_.find(tag);
  return it == curves_.end() ? nullptr : &it->second;
}

const ModelCurveLoop* Model::curve_loop(int tag) const {
  auto it = loops_.find(tag);
  return it == loops_.end() ? nullptr : &it->second;
}

const ModelSurface* Model::surface(int tag) const {
  auto it = surfaces_.find(tag);
  return it == surfaces_.end() ? nullptr : &it->second;
}

const PhysicalGroup* Model::physical(int dim, int tag) const {
  auto it = physicals_.find({dim, tag});
  return it == physicals_.end() ? nullptr : &it->second;
}

const SurfaceGeometry* Model::geometry(int tag) const {
  auto it = geometries_.find(tag);
  return it == geometries_.end() ? nullptr : &it->second;
}

std::vector<int> Model::physical_entities(int dim, int tag) const {
  std::vector<int> out;
  if (const PhysicalGroup* g = physical(dim, tag))
    for (int e : g->entities)
      if (has(dim, std::abs(e))) out.push_back(std::abs(e));
  return out;
}

bool Model::has(int dim, int tag) const {
  switch (dim) {
    case 0: return vertices_.count(tag) > 0;
    case 1: return curves_.count(tag) > 0;
    case 2: return surfaces_.count(tag) > 0;
    case 3: return volumes_.count(tag) > 0;
    default: return false;
  }
}

std::vector<int> Model::tags(int dim) const {
  std::vector<int> out;
  auto collect = [&out](const auto& m) {
    out.reserve(m.size());
    for (const auto& kv : m) out.push_back(kv.first);
  };
  if (dim == 0) collect(vertices_);
  else if (dim == 1) collect(curves_);
  else if (dim == 2) collect(surfaces_);
  else if (dim == 3) collect(volumes_);
  return out;
}

BoundingBox Model::curve_bounding_box(int tag) const {
  BoundingBox b;
  const ModelCurve* c = curve(std::abs(tag));
  if (!c) return b;
  const int n = 16 * c->shape->pieces();
  for (int i = 0; i <= n; ++i) b.add(c->shape->point(static_cast<double>(i) / n));
  return b;
}

BoundingBox Model::surface_bounding_box(int tag) const {
  BoundingBox b;
  const ModelSurface* s = surface(tag);
  if (!s) return b;
  for (int l : s->loops)
    for (int c : loops_.at(std::abs(l)).curves) {
      const BoundingBox cb = curve_bounding_box(c);
      if (!cb.empty()) {
        b.add(cb.lo);
        b.add(cb.hi);
      }
    }
  return b;
}

std::vector<int> Model::in_bounding_box(int dim, Vec3 lo, Vec3 hi) const {
  auto inside = [&](Vec3 p) {
    return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
  };
  std::vector<int> out;
  if (dim == 0) {
    for (const auto& [t, v] : vertices_)
      if (inside(v.xyz)) out.push_back(t);
  } else if (dim == 1 || dim == 2) {
    for (int t : tags(dim)) {
      const BoundingBox b = dim == 1 ? curve_bounding_box(t) : surface_bounding_box(t);
      if (!b.empty() && inside(b.lo) && inside(b.hi)) out.push_back(t);
    }
  }
  return out;
}

std::vector<int> Model::loop_tags() const {
  std::vector<int> out;
  for (const auto& kv : loops_) out.push_back(kv.first);
  return out;
}

BoundingBox Model::bounding_box() const {
  BoundingBox b;
  for (const auto& [t, v] : vertices_) b.add(v.xyz);
  return b;
}

// ---- surface geometries ----

GeoStatus Model::add_sphere_geometry(int tag, int centre_point, int pole_point, bool polar) {
  touch();
  if (tag <= 0 || geometries_.count(tag))
    return check_new_tag(EntityKind::SurfaceGeometry, tag, geometries_.count(tag) > 0);
  const ModelVertex* c = vertex(centre_point);
  const ModelVertex* p = vertex(pole_point);
  const char* what = polar ? "PolarSphere" : "Sphere";
  if (!c) return missing(GeoErrorId::UnknownPartOf, EntityKind::Point, centre_point, {tag}, {"centre", what});
  if (!p) return missing(GeoErrorId::UnknownPartOf, EntityKind::Point, pole_point, {tag}, {"pole", what});
  const double r = norm(p->xyz - c->xyz);
  if (!(r > 0))
    return make_error(GeoErrorId::SphereRadiusZero, EntityKind::SurfaceGeometry, {tag, centre_point, pole_point}, {},
                      {}, {what});
  if (polar) geometries_.emplace(tag, SurfaceGeometry(PolarSphere(c->xyz, r)));
  else geometries_.emplace(tag, SurfaceGeometry(Sphere(c->xyz, r)));
  current_geometry_ = tag;
  return {};
}

GeoStatus Model::add_polar_sphere(int tag, int c, int p) { return add_sphere_geometry(tag, c, p, true); }
GeoStatus Model::add_lonlat_sphere(int tag, int c, int p) { return add_sphere_geometry(tag, c, p, false); }

GeoStatus Model::set_current_geometry(int tag) {
  touch();
  if (!geometry(tag)) return missing(GeoErrorId::UnknownEntity, EntityKind::SurfaceGeometry, tag);
  current_geometry_ = tag;
  return {};
}

// ---- points ----

namespace {

GeoStatus check_finite(int tag, std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v))
      return make_error(GeoErrorId::PointNotFinite, EntityKind::Point, {tag}, {}, {v});
  return {};
}

}  // namespace

GeoStatus Model::add_point(int tag, Vec3 coords, double lc) {
  touch();
  if (current_geometry_) return add_point_on_geometry(tag, current_geometry_, {coords.x, coords.y}, lc);
  if (auto s = check_new_tag(EntityKind::Point, tag, vertices_.count(tag) > 0); !s) return s;
  if (auto s = check_finite(tag, {coords.x, coords.y, coords.z, lc}); !s) return s;
  ModelVertex v;
  v.tag = tag;
  v.xyz = coords;
  v.lc = lc > 0 ? lc : kMaxLc;
  vertices_.emplace(tag, v);
  bump_max(0, tag);
  return {};
}

GeoStatus Model::add_point_on_geometry(int tag, int geometry_tag, Vec2 uv, double lc) {
  touch();
  if (auto s = check_new_tag(EntityKind::Point, tag, vertices_.count(tag) > 0); !s) return s;
  const SurfaceGeometry* g = geometry(geometry_tag);
  if (!g) return missing(GeoErrorId::UnknownGeometryOfPoint, EntityKind::SurfaceGeometry, geometry_tag, {tag});
  if (auto s = check_finite(tag, {uv.x, uv.y, lc}); !s) return s;
  ModelVertex v;
  v.tag = tag;
  v.geometry = geometry_tag;
  v.uv = uv;
  v.xyz = g->point(uv);
  v.lc = lc > 0 ? lc : kMaxLc;
  vertices_.emplace(tag, v);
  bump_max(0, tag);
  return {};
}

GeoStatus Model::set_mesh_size(const std::vector<int>& points, double lc) {
  touch();
  if (!std::isfinite(lc))
    return make_error(GeoErrorId::MeshSizeNotFinite, EntityKind::Point, points, {}, {lc});
  for (int p : points) {
    if (vertex(p)) {
      vertices_[p].lc = lc > 0 ? lc : kMaxLc;
    } else {
      note_compat(CompatNoteId::MeshSizeOfMissingPoint, {p});
    }
  }
  return {};
}

// ---- curves ----

GeoResult<Curve> Model::build_shape(const ModelCurve& c) const {
  CurveDef d;
  d.kind = c.kind;
  d.tag = c.tag;
  d.periodic = c.points.size() > 2 && c.points.front() == c.points.back();
  d.plane_normal = c.plane_normal;
  d.xyz.reserve(c.points.size());
  if (c.geometry) {
    d.surface = geometries_.at(c.geometry);
    d.uv.reserve(c.points.size());
  }
  for (int p : c.points) {
    const ModelVertex& v = vertices_.at(p);
    d.xyz.push_back(v.xyz);
    if (c.geometry) d.uv.push_back(v.uv);
  }
  if (c.discrete) {   // the polyline through the nodes between its two points
    d.periodic = false;
    d.xyz.insert(d.xyz.begin() + 1, c.inner.begin(), c.inner.end());
  }
  return Curve::make(std::move(d));
}

GeoStatus Model::add_discrete_curve(int tag, int begin, int end, std::vector<Vec3> inner) {
  touch();
  if (auto s = check_new_tag(EntityKind::Curve, tag, curves_.count(tag) > 0); !s) return s;
  for (int p : {begin, end})
    if (!vertex(p)) return missing(GeoErrorId::UnknownEntityUsedBy, EntityKind::Point, p, {tag}, {"discrete curve"});
  if (begin == end && inner.size() < 2)
    return make_error(GeoErrorId::DiscreteCurveClosed, EntityKind::Curve, {tag, begin});
  ModelCurve c;
  c.tag = tag;
  c.kind = CurveKind::Line;
  c.points = {begin, end};
  c.begin = begin, c.end = end;
  c.discrete = true;
  c.inner = std::move(inner);
  auto shape = build_shape(c);
  if (!shape) return shape.error();
  c.shape = std::move(*shape);
  curves_.emplace(tag, std::move(c));
  bump_max(1, tag);
  return {};
}

GeoStatus Model::give_geometry_to_discrete_curve(int tag) {
  auto it = curves_.find(tag);
  if (it == curves_.end() || !it->second.discrete)
    return missing(GeoErrorId::UnknownEntityUsedBy, EntityKind::Curve, tag, {tag}, {"CreateGeometry"});
  touch();
  it->second.has_geometry = true;
  return {};
}

GeoStatus Model::add_surface_of_discrete_mesh(int tag, const std::vector<std::vector<int>>& loops) {
  std::vector<int> loop_tags;
  for (const std::vector<int>& curves : loops) {
    std::vector<LoopEdge> edges;
    for (int c : curves) {
      const ModelCurve* mc = curve(c);
      if (!mc) return missing(GeoErrorId::UnknownEntityIn, EntityKind::Curve, c, {tag}, {"plane surface"});
      edges.push_back({c, mc->begin, mc->end});
    }
    ModelCurveLoop l;
    l.tag = std::numeric_limits<int>::max() - hidden_loop_tag_++;
    auto chained = chain_loop_reorienting(l.tag, edges);
    if (!chained) return chained.error();
    l.curves = std::move(*chained);
    loop_tags.push_back(l.tag);
    loops_.emplace(l.tag, std::move(l));
  }
  return add_plane_surface(tag, loop_tags);
}

GeoStatus Model::add_curve(int tag, CurveKind kind, const std::vector<int>& points, std::optional<Vec3> plane_normal) {
  touch();
  if (auto s = check_new_tag(EntityKind::Curve, tag, curves_.count(tag) > 0); !s) return s;
  for (int p : points)
    if (!vertex(p)) return missing(GeoErrorId::UnknownEntityUsedBy, EntityKind::Point, p, {tag}, {to_string(kind)});
  if (points.size() == 2 && points[0] == points[1]) {
    if (kind == CurveKind::Line) {
      // Gmsh keeps such a line as a degenerate curve that gets no mesh elements. We
      // create no curve (a later use of it is an error) but take its tag, as Gmsh does.
      note_compat(CompatNoteId::LineToItself, {tag, points[0]});
      bump_max(1, tag);
      return {};
    }
    return make_error(GeoErrorId::CurveStartsAtEnd, EntityKind::Curve, {tag, points[0]}, {}, {}, {to_string(kind)});
  }
  // A zero-length piece of a Line or Spline: the same point twice in a row. (B-splines and
  // Bezier curves may repeat control points: Gmsh uses that to sharpen them.)
  const bool interpolating = kind == CurveKind::Line || kind == CurveKind::Spline;
  for (std::size_t i = 0; interpolating && i + 1 < points.size(); ++i)
    if (points[i] == points[i + 1])
      return make_error(GeoErrorId::CurvePointTwice, EntityKind::Curve, {tag, points[i]}, {}, {}, {to_string(kind)});
  if ((kind == CurveKind::Circle || kind == CurveKind::Ellipse) && points.size() >= 3) {
    const int centre = points[1];
    if (points.front() == centre || points.back() == centre || points.front() == points.back())
      return make_error(GeoErrorId::ArcRepeatsPoint, EntityKind::Curve, {tag}, {}, {}, {to_string(kind)});
  }
  std::vector<int> control = points;
  if (kind == CurveKind::Ellipse && points.size() == 4 && vertices_.at(points[2]).xyz == vertices_.at(points[1]).xyz) {
    // Gmsh's ellipse then measures the major axis's angle from a zero vector, which is
    // 0: the direction of the start point. We use the start point as the major-axis point.
    note_compat(CompatNoteId::EllipseAxisAtCentre, {tag, points[2], points[0]});
    control[2] = points[0];
  }
  ModelCurve c;
  c.tag = tag;
  c.kind = kind;
  c.points = control;
  c.plane_normal = plane_normal;
  if (!points.empty()) {
    c.begin = points.front();
    c.end = points.back();
    // Gmsh: the curve lies on a geometry when all its control points do.
    const int g = vertices_.at(points.front()).geometry;
    bool same = g != 0;
    for (int p : points) same = same && vertices_.at(p).geometry == g;
    c.geometry = same ? g : 0;
  }
  auto shape = build_shape(c);
  if (!shape) return shape.error();
  c.shape = std::move(*shape);
  if (collapses(*this, c))
    note_compat(CompatNoteId::ZeroLengthCurve, {tag, c.begin, c.end}, to_string(kind));
  curves_.emplace(tag, std::move(c));
  bump_max(1, tag);
  return {};
}

GeoStatus Model::rebuild_curves_using(const std::vector<int>& moved_points) {
  touch();
  std::vector<int> sorted = moved_points;
  std::sort(sorted.begin(), sorted.end());
  GeoStatus status;
  for (auto& [t, c] : curves_) {
    bool hit = false;
    for (int p : c.points) hit = hit || std::binary_search(sorted.begin(), sorted.end(), p);
    if (!hit) continue;
    // A non-uniform dilation can make an arc invalid: the first such failure is reported
    // (and the transform undone by the caller).
    auto shape = build_shape(c);
    if (shape) c.shape = std::move(*shape);
    else if (status.ok()) status = shape.error();
  }
  return status;
}

// ---- curve loops ----

GeoStatus Model::add_curve_loop(int tag, const std::vector<int>& curves) {
  touch();
  if (auto s = check_new_tag(EntityKind::CurveLoop, tag, loops_.count(tag) > 0); !s) return s;
  if (curves.empty())
    return make_error(GeoErrorId::LoopEmpty, EntityKind::CurveLoop, {tag});
  std::vector<LoopEdge> edges;
  edges.reserve(curves.size());
  for (int sc : curves) {
    const ModelCurve* c = curve(std::abs(sc));
    if (sc == 0 || !c) return missing(GeoErrorId::UnknownEntityIn, EntityKind::Curve, sc, {tag}, {"curve loop"});
    edges.push_back(sc > 0 ? LoopEdge{sc, c->begin, c->end} : LoopEdge{sc, c->end, c->begin});
  }
  auto chained = chain_loop(tag, edges);
  if (!chained && chained.error().kind != GeoErrorKind::LoopNotClosed) return chained.error();
  ModelCurveLoop l;
  l.tag = tag;
  const bool has_discrete = std::any_of(curves.begin(), curves.end(), [&](int sc) { return curve(std::abs(sc))->discrete; });
  if (!chained && has_discrete) {
    if (auto reoriented = chain_loop_reorienting(tag, edges)) {
      // Gmsh meshes a loop of discrete curves as its edges come, whatever their signs.
      const auto flipped = std::find_if(reoriented->begin(), reoriented->end(), [&](int sc) {
        return std::find(curves.begin(), curves.end(), sc) == curves.end();
      });
      compat_notes_.push_back({CompatNoteId::DiscreteLoopReoriented, {tag, -*flipped}, {}, {}});
      chained = std::move(reoriented);
    }
  }
  if (!chained) {
    compat_notes_.push_back({CompatNoteId::UncheckedLoop, {}, {}, chained.error()});
    l.curves = curves;
    l.unclosed = chained.error();
  } else {
    l.curves = std::move(*chained);
  }
  l.reordered = l.curves != curves;
  loops_.emplace(tag, std::move(l));
  bump_max(kLoopSlot, tag);
  return {};
}

// ---- plane surfaces ----

GeoStatus Model::add_plane_surface(int tag, const std::vector<int>& loops) {
  touch();
  if (auto s = check_new_tag(EntityKind::Surface, tag, surfaces_.count(tag) > 0); !s) return s;
  if (loops.empty())
    return make_error(GeoErrorId::NoLoop, EntityKind::Surface, {tag}, {}, {}, {"plane surface", "curve loop"});
  for (int l : loops) {
    if (l == 0 || !curve_loop(std::abs(l)))
      return missing(GeoErrorId::UnknownEntityIn, EntityKind::CurveLoop, l, {tag}, {"plane surface"});
    if (const auto& open = curve_loop(std::abs(l))->unclosed) return *open;
  }
  for (std::size_t i = 0; i < loops.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(loops[i]) == std::abs(loops[j]))
        return make_error(GeoErrorId::LoopTwice, EntityKind::Surface, {tag, std::abs(loops[i])});
  // No curve may appear in two loops of one surface (a seam may appear twice in one loop).
  std::map<int, int> owner;   // |curve| -> loop
  int geometry_tag = -1;
  for (int l : loops) {
    for (int sc : loops_.at(std::abs(l)).curves) {
      const int c = std::abs(sc);
      auto [it, fresh] = owner.emplace(c, l);
      if (!fresh && std::abs(it->second) != std::abs(l))
        return make_error(GeoErrorId::CurveInTwoLoops, EntityKind::Surface, {tag, c, it->second, l});
      const int g = curves_.at(c).geometry;
      geometry_tag = geometry_tag == -1 ? g : (geometry_tag == g ? g : 0);
    }
  }
  ModelSurface s;
  s.tag = tag;
  s.loops = loops;
  s.geometry = std::max(geometry_tag, 0);
  // Holes must lie inside the outer loop: checked in the surface's parameter plane.
  const SurfaceGeometry* g = s.geometry ? &geometries_.at(s.geometry) : nullptr;
  std::vector<LoopPolygon> probes;   // each loop probed once, then tried as a hole of each outer candidate
  probes.reserve(loops.size());
  for (std::size_t i = 1; i < loops.size(); ++i)
    probes.push_back(probe_loop(*this, loops_.at(std::abs(loops[i])), g, 16));
  // Where each other loop lies with loops[outer_index] as the outer one: the loops wholly
  // outside it and those partly outside (some probe points in, some out).
  struct Placement {
    std::vector<std::size_t> outside, crossing;
  };
  auto place = [&](std::size_t outer_index) {
    LoopPolygon outer = sample_loop(*this, loops_.at(std::abs(loops[outer_index])), g);
    PlaneFrame frame = g ? PlaneFrame{} : plane_frame(outer.xyz);
    const PolygonIndex outer2(g ? outer.uv : frame.project(outer.xyz));
    Placement p;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      if (i == outer_index) continue;
      const LoopPolygon probe = i == 0 ? probe_loop(*this, loops_.at(std::abs(loops[0])), g, 16) : probes[i - 1];
      const std::vector<Vec2> pts = g ? probe.uv : frame.project(probe.xyz);
      const std::size_t in = static_cast<std::size_t>(
          std::count_if(pts.begin(), pts.end(), [&](Vec2 q) { return outer2.contains(q); }));
      if (in == 0) p.outside.push_back(i);
      else if (in < pts.size()) p.crossing.push_back(i);
    }
    return p;
  };
  Placement first = place(0);
  if (!first.outside.empty() || !first.crossing.empty()) {
    // Gmsh meshes the region the loops bound whatever their order: the loop that encloses
    // all the others is the outer one. Failing that, one that has no other loop wholly
    // outside it: Gmsh meshes the curves as discretised, and a hole that crosses the outer
    // loop only at a scale below the mesh size meshes (benchmarks/2d_large/mediterranean.geo).
    // The 1D mesher refuses mesh edges that cross (mesh/boundary_recovery.cpp). A loop wholly
    // outside the outer one would leave a wrong mesh in Gmsh: that stays an error.
    std::size_t outer = loops.size();
    Placement chosen;
    for (int pass = 0; pass < 2 && outer == loops.size(); ++pass)
      for (std::size_t i = 0; i < loops.size() && outer == loops.size(); ++i) {
        Placement p = i == 0 ? first : place(i);
        if (p.outside.empty() && (pass == 1 || p.crossing.empty())) {
          outer = i;
          chosen = std::move(p);
        }
      }
    if (outer == loops.size()) {
      // On a PolarSphere (u,v) is a stereographic plane: the face is the bounded side of its
      // outer loop there. Holes all beyond it (benchmarks/2d/world.geo: a small outer loop
      // round the plane's origin, the continents around it) mean the sea on the other side,
      // which holds the projection pole, the plane's infinity, where no face can reach.
      // Gmsh 4.8.4 reports nothing and meshes the inside of one of the loops that no other
      // encloses, whichever its Delaunay edge list meets first, not the first listed
      // (docs/language.md): no rule of the script's own picks it, so it stays our error.
      const bool pole_side = g && g->polar() && first.crossing.empty() && first.outside.size() + 1 == loops.size();
      const std::size_t bad = first.outside.empty() ? first.crossing.front() : first.outside.front();
      const int l = std::abs(loops[bad]);
      if (pole_side)
        return make_error(GeoErrorId::HoleOutsidePolar, EntityKind::Surface, {tag, l, std::abs(loops[0])},
                          {s.geometry});
      return make_error(GeoErrorId::HoleOutside, EntityKind::Surface, {tag, l, std::abs(loops[0])});
    }
    if (outer != 0) {
      note_compat(CompatNoteId::OuterListedLater, {tag, std::abs(loops[outer]), std::abs(loops[0])});
      std::rotate(s.loops.begin(), s.loops.begin() + static_cast<std::ptrdiff_t>(outer),
                  s.loops.begin() + static_cast<std::ptrdiff_t>(outer) + 1);
      s.listed_outer = outer;
    }
    for (std::size_t i : chosen.crossing)
      note_compat(CompatNoteId::HoleCrossesOuter, {tag, std::abs(loops[i]), std::abs(loops[outer])});
  }
  surfaces_.emplace(tag, std::move(s));
  bump_max(2, tag);
  return {};
}

// ---- physical groups ----

GeoResult<int> Model::add_physical(int dim, std::optional<int> tag, const std::string& name,
                                   const std::vector<int>& entities, PhysicalOp op) {
  touch();
  if (dim < 0 || dim > 3)
    return make_error(GeoErrorId::PhysicalDimension, EntityKind::Physical, {}, {dim});
  for (int e : entities) {
    const int a = std::abs(e);
    const bool ok = (dim == 0 && vertex(a)) || (dim == 1 && curve(a)) || (dim == 2 && surface(a)) ||
                    (dim == 3 && volumes_.count(a));
    if (!ok) return missing(GeoErrorId::UnknownInPhysicalGroup, static_cast<EntityKind>(dim), e);
  }
  int t = 0;
  if (tag) {
    t = *tag;
    if (t < 0 || (t == 0 && physicals_.count({dim, 0}) == 0))
      if (auto st = check_new_tag(EntityKind::Physical, t, false); !st) return st.error();
  } else {
    // A name alone reuses the group of that name in this dimension, else takes 1 + the
    // largest physical tag of any dimension.
    for (const auto& [key, g] : physicals_)
      if (g.dim == dim && g.name == name) t = g.tag;
    if (!t) t = max_physical_tag_ + 1;
  }
  auto it = physicals_.find({dim, t});
  if (op == PhysicalOp::Assign) {
    if (it != physicals_.end())
      return make_error(GeoErrorId::PhysicalAlreadyExists, EntityKind::Physical, {t}, {}, {},
                        {to_string(static_cast<EntityKind>(dim))});
    PhysicalGroup g;
    g.dim = dim;
    g.tag = t;
    g.name = name;
    g.entities = entities;
    physicals_.emplace(std::make_pair(dim, t), std::move(g));
    max_physical_tag_ = std::max(max_physical_tag_, t);
    return t;
  }
  if (it == physicals_.end()) {
    if (op == PhysicalOp::Remove) return missing(GeoErrorId::UnknownEntity, EntityKind::Physical, t);
    PhysicalGroup g;   // += creates the group, as Gmsh does
    g.dim = dim;
    g.tag = t;
    g.name = name;
    it = physicals_.emplace(std::make_pair(dim, t), std::move(g)).first;
    max_physical_tag_ = std::max(max_physical_tag_, t);
  }
  auto& list = it->second.entities;
  if (op == PhysicalOp::Add) {
    // Gmsh's List_Insert: an entity (with its sign) already in the group is not added again.
    for (int e : entities)
      if (std::find(list.begin(), list.end(), e) == list.end()) list.push_back(e);
  } else {
    for (int e : entities) {
      auto f = std::find(list.begin(), list.end(), e);
      if (f != list.end()) list.erase(f);
    }
  }
  return t;
}

GeoStatus Model::embed(int dim, const std::vector<int>& tags_in, int surface_tag) {
  touch();
  auto it = surfaces_.find(surface_tag);
  if (it == surfaces_.end()) return missing(GeoErrorId::UnknownEmbeddingTarget, EntityKind::Surface, surface_tag);
  for (int t : tags_in) {
    if (dim == 0 && !vertex(t)) return missing(GeoErrorId::UnknownEmbedded, EntityKind::Point, t, {surface_tag});
    if (dim == 1 && !curve(std::abs(t)))
      return missing(GeoErrorId::UnknownEmbedded, EntityKind::Curve, t, {surface_tag});
  }
  if (dim != 0 && dim != 1)
    return make_error(GeoErrorId::EmbedDimension, EntityKind::Surface, {surface_tag});
  auto& list = dim == 0 ? it->second.embedded_points : it->second.embedded_curves;
  for (int t : tags_in)
    if (std::find(list.begin(), list.end(), std::abs(t)) == list.end()) list.push_back(std::abs(t));
  return {};
}

// ---- queries ----

GeoResult<std::vector<DimTag>> Model::boundary(const std::vector<DimTag>& entities, bool combined) const {
  std::vector<DimTag> raw;
  for (const DimTag& e : entities) {
    const int a = std::abs(e.tag);
    if (e.dim == 0) {
      if (!vertex(a)) return missing(GeoErrorId::UnknownInBoundary, EntityKind::Point, a);
    } else if (e.dim == 1) {
      const ModelCurve* c = curve(a);
      if (!c) return missing(GeoErrorId::UnknownInBoundary, EntityKind::Curve, e.tag);
      // Oriented: the start point counts negatively, the end positively.
      const int b = e.tag > 0 ? c->begin : c->end, f = e.tag > 0 ? c->end : c->begin;
      raw.push_back({0, -b});
      raw.push_back({0, f});
    } else if (e.dim == 2) {
      const ModelSurface* s = surface(a);
      if (!s) return missing(GeoErrorId::UnknownInBoundary, EntityKind::Surface, e.tag);
      // In the script's order (an outer loop listed after a hole moved to the front).
      std::vector<int> listed = s->loops;
      std::rotate(listed.begin(), listed.begin() + 1,
                  listed.begin() + static_cast<std::ptrdiff_t>(s->listed_outer) + 1);
      for (std::size_t i = 0; i < listed.size(); ++i) {
        // As Gmsh lists them (setSurfaceGeneratrices): every loop after the first listed one
        // reversed (its curves negated, in reverse order), so that holes run against the
        // outer loop; the sign of the surface tag itself is ignored.
        const int l = listed[i];
        const auto& cs = loops_.at(std::abs(l)).curves;
        const int sign = (l > 0) == (i == 0) ? 1 : -1;
        if (sign > 0)
          for (int c : cs) raw.push_back({1, c});
        else
          for (auto it = cs.rbegin(); it != cs.rend(); ++it) raw.push_back({1, -*it});
      }
    } else if (e.dim == 3) {
      const auto v = volumes_.find(a);
      if (v == volumes_.end()) return missing(GeoErrorId::UnknownInBoundary, EntityKind::Volume, a);
      for (int t : v->second.surfaces) raw.push_back({2, t});   // signed by orientation (geo/extrude.cpp)
    } else {
      return make_error(GeoErrorId::BoundaryDimension, EntityKind::None, {e.tag}, {e.dim});
    }
  }
  std::vector<DimTag> out;
  if (!combined) {
    // Gmsh prints point tags unsigned and keeps curve signs.
    for (DimTag d : raw) out.push_back({d.dim, d.dim == 0 ? std::abs(d.tag) : d.tag});
    return out;
  }
  // Combined, as Gmsh 4.8.4 (GModel::getBoundaryTags): an entity seen an even number of
  // times cancels whatever its signs (two surfaces written with the same orientation of
  // their shared curve still share it); the rest is listed by dimension, then by |tag|, with
  // the sign of its first appearance.
  std::map<std::pair<int, int>, std::pair<int, int>> seen;   // (dim, |tag|) -> (count, first tag)
  for (DimTag d : raw) {
    auto [it, fresh] = seen.emplace(std::make_pair(d.dim, std::abs(d.tag)), std::make_pair(0, d.tag));
    ++it->second.first;
  }
  for (const auto& [key, v] : seen) {
    if (v.first % 2 == 0) continue;
    out.push_back({key.first, key.first == 0 ? key.second : v.second});
  }
  return out;
}

// ---- filling surfaces ----

GeoStatus Model::add_surface_filling(int tag, const std::vector<int>& loops, std::optional<int> sphere_centre) {
  touch();
  if (auto s = check_new_tag(EntityKind::Surface, tag, surfaces_.count(tag) > 0); !s) return s;
  if (loops.empty())
    return make_error(GeoErrorId::NoLoop, EntityKind::Surface, {tag}, {}, {}, {"surface", "curve loop"});
  // Gmsh 4.8.4 (Geo/GModelIO_GEO.cpp's addSurfaceFilling): the first loop, of 3 or 4
  // curves, is the patch; the others are holes in it (benchmarks/2d/ruled_on_sphere.geo).
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const ModelCurveLoop* h = curve_loop(std::abs(loops[i]));
    if (loops[i] == 0 || !h)
      return missing(GeoErrorId::UnknownEntityIn, EntityKind::CurveLoop, loops[i], {tag}, {"surface"});
    if (h->unclosed) return *h->unclosed;
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(loops[i]) == std::abs(loops[j]))
        return make_error(GeoErrorId::FillingLoopTwice, EntityKind::Surface, {tag, std::abs(loops[i])});
  }
  const ModelCurveLoop* l = curve_loop(std::abs(loops[0]));
  if (l->curves.size() != 3 && l->curves.size() != 4)
    return make_error(GeoErrorId::FillingCurveCount, EntityKind::Surface, {tag, std::abs(loops[0])},
                      {static_cast<int>(l->curves.size())});
  if (sphere_centre && !vertex(*sphere_centre))
    return missing(GeoErrorId::UnknownPartOf, EntityKind::Point, *sphere_centre, {tag}, {"sphere centre", "surface"});
  ModelSurface s;
  s.tag = tag;
  s.filling = true;
  s.sphere_centre = sphere_centre.value_or(0);
  s.loops = loops;
  int g = -1;
  for (int c : l->curves) {
    const int cg = curves_.at(std::abs(c)).geometry;
    g = g == -1 ? cg : (g == cg ? g : 0);
  }
  s.geometry = std::max(g, 0);
  surfaces_.emplace(tag, std::move(s));
  bump_max(2, tag);
  return {};
}

GeoResult<Vec3> Model::surface_point(int tag, Vec2 uv) const {
  const ModelSurface* s = surface(tag);
  if (!s) return missing(GeoErrorId::UnknownEntity, EntityKind::Surface, tag);
  if (s->geometry) return geometries_.at(s->geometry).point(uv);
  if (!s->filling)
    return make_error(GeoErrorId::PlaneSurfaceNoUv, EntityKind::Surface, {tag});
  return filling_patch(*s).point(uv);
}

TransfinitePatch Model::filling_patch(const ModelSurface& surf) const {
  const ModelSurface* s = &surf;
  // Loop orientation: a negative loop tag reverses the loop.
  std::vector<int> cs = loops_.at(std::abs(s->loops[0])).curves;
  if (s->loops[0] < 0) {
    std::reverse(cs.begin(), cs.end());
    for (int& c : cs) c = -c;
  }
  TransfinitePatch patch;
  patch.old_style = options_.old_ruled_surface;
  for (int c : cs) patch.sides.push_back({&*curves_.at(std::abs(c)).shape, c < 0});
  if (s->sphere_centre) {
    patch.sphere_centre = vertices_.at(s->sphere_centre).xyz;
  } else {
    // Gmsh's guess: all sides are circles about the same centre point, not all in one plane.
    bool circles = true, one_plane = true;
    int centre = 0;
    Vec3 n0;
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const ModelCurve& c = curves_.at(std::abs(cs[i]));
      if (c.kind != CurveKind::Circle) {
        circles = false;
        break;
      }
      const CircleArc& a = *c.shape->circle();
      const Vec3 n = cross(a.x_axis, a.y_axis);
      if (i == 0) {
        centre = c.points[1];
        n0 = n;
      } else {
        circles = circles && c.points[1] == centre;
        one_plane = one_plane && norm(n - n0) < 1e-12;
      }
    }
    if (circles && !one_plane) patch.sphere_centre = vertices_.at(centre).xyz;
  }
  return patch;
}

GeoResult<std::optional<double>> Model::intersect_curve_surface(int curve_tag, int surface_tag) const {
  const ModelCurve* c = curve(curve_tag);
  if (!c || !c->shape)
    return make_error(GeoErrorId::UnknownToIntersect, EntityKind::Curve, {curve_tag}, {surface_tag});
  if (!surface(surface_tag)) return missing(GeoErrorId::UnknownEntity, EntityKind::Surface, surface_tag);
  // F(u, v, t) = S(u, v) - C(t) = 0 by Newton's method with a forward-difference Jacobian,
  // as Gmsh does: at most 10 steps from (0.5, 0.5, 0.5), relative step 1e-4, converged when
  // the step is below 1e-6. A singular Jacobian or a runaway iterate is no intersection.
  double x[3] = {0.5, 0.5, 0.5};
  std::optional<GeoError> failed;
  auto f = [&](const double* a, double* out) {
    auto sp = surface_point(surface_tag, {a[0], a[1]});
    if (!sp) {
      failed = sp.error();
      return false;
    }
    const Vec3 d = *sp - c->shape->point(a[2]);
    out[0] = d.x, out[1] = d.y, out[2] = d.z;
    return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
  };
  for (int iter = 0; iter < 10; ++iter) {
    if (std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) > 1e6) break;
    double f0[3] = {0, 0, 0}, j[3][4] = {};
    if (!f(x, f0)) break;
    if (f0[0] == 0 && f0[1] == 0 && f0[2] == 0) return std::optional<double>(x[2]);
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      double h = 1e-4 * std::fabs(x[k]);
      if (h == 0) h = 1e-4;
      double xh[3] = {x[0], x[1], x[2]}, fh[3] = {0, 0, 0};
      xh[k] += h;
      ok = f(xh, fh);
      for (int r = 0; r < 3; ++r) j[r][k] = (fh[r] - f0[r]) / h;
    }
    if (!ok) break;
    for (int r = 0; r < 3; ++r) j[r][3] = f0[r];
    // Gaussian elimination with partial pivoting on the 3x4 system J dx = f.
    for (int col = 0; col < 3 && ok; ++col) {
      int piv = col;
      for (int r = col + 1; r < 3; ++r)
        if (std::fabs(j[r][col]) > std::fabs(j[piv][col])) piv = r;
      if (j[piv][col] == 0) ok = false;
      if (!ok) break;
      for (int k = 0; k < 4; ++k) std::swap(j[col][k], j[piv][k]);
      for (int r = col + 1; r < 3; ++r) {
        const double m = j[r][col] / j[col][col];
        for (int k = col; k < 4; ++k) j[r][k] -= m * j[col][k];
      }
    }
    if (!ok) break;
    double dx[3] = {0, 0, 0};
    for (int r = 2; r >= 0; --r) {
      double v = j[r][3];
      for (int k = r + 1; k < 3; ++k) v -= j[r][k] * dx[k];
      dx[r] = v / j[r][r];
    }
    for (int k = 0; k < 3; ++k) x[k] -= dx[k];
    if (std::sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]) < 1e-6) return std::optional<double>(x[2]);
  }
  if (failed) return *failed;
  return std::optional<double>{};
}

bool collapses(const Model& m, const ModelCurve& c) {
  if (c.begin == c.end || c.points.size() < 2) return false;
  if (c.kind == CurveKind::Circle || c.kind == CurveKind::Ellipse) return false;
  const ModelVertex* first = m.vertex(c.points.front());
  if (!first) return false;
  // "The same place" within Geometry.Tolerance relative to the point's distance from the
  // origin (at least 1): the bounding box would cost a pass per curve, and points written
  // as 0.2 + 0.1 and 0.3 must meet.
  const double tol = m.options().tolerance * std::max(1.0, norm(first->xyz));
  for (int p : c.points) {
    const ModelVertex* v = m.vertex(p);
    if (!v || norm(v->xyz - first->xyz) > tol) return false;
  }
  return true;
}

}  // namespace sm::geo
