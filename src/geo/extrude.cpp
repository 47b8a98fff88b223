// Gmsh 4.8.4's Extrude in the built-in kernel (Geo/Geo.cpp's ExtrudePoint, ExtrudeCurve,
// ExtrudeSurface and ExtrudeShapes, read for their meaning), with its tag order: the top
// copy first (a Duplicata, geo/model_edit.cpp), then one new point and one curve per swept
// end point, then the swept surface; a swept surface's top copy is renumbered last. Gmsh
// creates the copies' points again for each end and lets the coherence that ends the
// statement (Geometry.AutoCoherence) merge them, which sets the next tags: so do we.
// Surface Loop and Volume are kept as entities here too (nothing meshes volumes).
#include <algorithm>
#include <cmath>
#include <limits>


#include "geo/model.h"

namespace sm::geo {

namespace {

Vec3 rotate_about(Vec3 p, Vec3 axis, Vec3 point, double angle) {
  const double n = norm(axis);
  if (!(n > 0)) return p;
  const Vec3 k = axis / n;
  const Vec3 v = p - point;
  const double c = std::cos(angle), s = std::sin(angle);
  // Rodrigues' formula.
  return point + v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

}  // namespace

std::vector<double> ExtrudeLayers::fractions() const {
  std::vector<double> out{0.0};
  double t0 = 0;
  for (std::size_t i = 0; i < elements.size() && i < heights.size(); ++i) {
    const double t1 = heights[i];
    for (int j = 1; j <= elements[i]; ++j) out.push_back(t0 + (t1 - t0) * j / elements[i]);
    t0 = t1;
  }
  return out;
}

Vec3 extrude_point(const ExtrudeSpec& s, Vec3 p, double t) {
  switch (s.kind) {
    case ExtrudeKind::Translate: return p + s.translation * t;
    case ExtrudeKind::Rotate: return rotate_about(p, s.axis, s.point, s.angle * t);
    case ExtrudeKind::Twist: return rotate_about(p, s.axis, s.point, s.angle * t) + s.translation * t;
  }
  return p;
}

GeoStatus Model::add_surface_loop(int tag, const std::vector<int>& surfaces) {
  touch();
  if (tag <= 0)
    return make_error(GeoErrorId::TagMustBePositive, EntityKind::SurfaceLoop, {tag});
  if (surface_loops_.count(tag))
    return make_error(GeoErrorId::AlreadyExists, EntityKind::SurfaceLoop, {tag});
  for (int s : surfaces)
    if (!surfaces_.count(std::abs(s)))
      return make_error(GeoErrorId::UnknownEntityIn, EntityKind::Surface, {std::abs(s), tag}, {}, {}, {"surface loop"});
  if (surfaces.empty())
    return make_error(GeoErrorId::LoopEmpty, EntityKind::SurfaceLoop, {tag});
  surface_loops_[tag] = ModelSurfaceLoop{tag, surfaces};
  bump_max(kSurfaceLoopSlot, tag);
  return {};
}

GeoStatus Model::add_volume(int tag, const std::vector<int>& loops) {
  touch();
  if (tag <= 0)
    return make_error(GeoErrorId::TagMustBePositive, EntityKind::Volume, {tag});
  if (volumes_.count(tag))
    return make_error(GeoErrorId::AlreadyExists, EntityKind::Volume, {tag});
  if (loops.empty())
    return make_error(GeoErrorId::NoLoop, EntityKind::Volume, {tag}, {}, {}, {"volume", "surface loop"});
  for (int l : loops)
    if (!surface_loops_.count(std::abs(l)))
      return make_error(GeoErrorId::UnknownEntityIn, EntityKind::SurfaceLoop, {std::abs(l), tag}, {}, {}, {"volume"});
  ModelVolume v;
  v.tag = tag;
  v.loops = loops;
  for (int l : loops)
    for (int s : surface_loops_.at(std::abs(l)).surfaces) v.surfaces.push_back(s);
  volumes_[tag] = std::move(v);
  bump_max(3, tag);
  return {};
}

const Extrusion* Model::extrusion(int dim, int tag) const {
  const auto it = extrusions_.find({dim, std::abs(tag)});
  return it == extrusions_.end() ? nullptr : &it->second;
}

// The copy moved as Gmsh's ApplyTransformationTo* moves it: no coherence in between.
GeoStatus Model::transform_by(const std::vector<DimTag>& entities, const ExtrudeSpec& spec) {
  const bool ac = options_.auto_coherence;
  options_.auto_coherence = false;
  GeoStatus st;
  switch (spec.kind) {
    case ExtrudeKind::Translate: st = translate(entities, spec.translation); break;
    case ExtrudeKind::Rotate: st = rotate(entities, spec.axis, spec.point, spec.angle); break;
    case ExtrudeKind::Twist:
      st = rotate(entities, spec.axis, spec.point, spec.angle);
      if (st) st = translate(entities, spec.translation);
      break;
  }
  options_.auto_coherence = ac;
  return st;
}

// ExtrudePoint: returns the top point; *body the swept curve (0: the point did not move,
// or its curve was merged into an existing one by the coherence of a final extrusion).
GeoResult<int> Model::extrude_point_entity(int p, const ExtrudeSpec& spec, int* body) {
  *body = 0;
  const auto vit = vertices_.find(p);
  if (vit == vertices_.end())
    return make_error(GeoErrorId::CannotActOnUnknown, EntityKind::Point, {p}, {}, {}, {"extrude"});
  const ModelVertex src = vit->second;
  const double diag = bounding_box().diagonal();
  const double eps = options_.tolerance * (diag > 0 ? diag : 1.0);
  auto new_point = [&](Vec3 at) {
    ModelVertex v = src;
    v.tag = new_point_tag();
    v.xyz = at;
    v.geometry = 0;
    bump_max(0, v.tag);
    const int t = v.tag;
    vertices_.emplace(t, v);
    return t;
  };
  int top = 0, curve = 0;
  if (spec.kind == ExtrudeKind::Twist) {
    // Geometry.ExtrudeSplinePoints steps, each turning by angle/n then moving by T/n.
    const int n = std::max(1, spec.spline_points);
    top = new_point(src.xyz);
    curve = new_curve_tag();
    std::vector<int> pts{p};
    Vec3 x = src.xyz;
    for (int i = 0; i < n; ++i) {
      if (i) top = new_point(x);
      x = rotate_about(x, spec.axis, spec.point, spec.angle / n) + spec.translation / static_cast<double>(n);
      vertices_.at(top).xyz = x;
      pts.push_back(top);
    }
    if (auto st = add_curve(curve, CurveKind::Spline, pts); !st) return st.error();
  } else {
    const Vec3 q = extrude_point(spec, src.xyz, 1.0);
    top = new_point(q);
    if (std::abs(q.x - src.xyz.x) <= eps && std::abs(q.y - src.xyz.y) <= eps && std::abs(q.z - src.xyz.z) <= eps)
      return p;   // on the rotation axis (or a zero translation): Gmsh sweeps nothing
    curve = new_curve_tag();
    if (spec.kind == ExtrudeKind::Translate) {
      if (auto st = add_curve(curve, CurveKind::Line, {p, top}); !st) return st.error();
    } else {
      if (std::abs(spec.angle) > kPi * (1 + 1e-12))
        return make_error(GeoErrorId::ExtrudedArcTooWide, EntityKind::Point, {p}, {}, {spec.angle});
      const Vec3 k = spec.axis / norm(spec.axis);
      const Vec3 centre = spec.point + k * dot(src.xyz - spec.point, k);
      bump_max(1, curve);   // Gmsh numbers the centre after the curve
      const int c = new_point(centre);
      const Vec3 normal = spec.angle < 0 ? k * -1.0 : k;
      if (auto st = add_curve(curve, CurveKind::Circle, {p, c, top}, normal); !st) return st.error();
    }
  }
  Extrusion e;
  e.spec = spec;
  e.source = p;
  extrusions_[{1, curve}] = e;
  *body = curve;
  return top;
}

namespace {

// Whether every control point of the curves lies in one plane (tolerance eps).
bool coplanar(const std::vector<Vec3>& pts, double eps) {
  if (pts.size() < 4) return true;
  Vec3 n{};
  for (std::size_t i = 0; i < pts.size(); ++i) n = n + cross(pts[i], pts[(i + 1) % pts.size()]);   // Newell
  for (std::size_t i = 1; i + 1 < pts.size() && !(norm(n) > 0); ++i) n = cross(pts[i] - pts[0], pts[i + 1] - pts[0]);
  const double len = norm(n);
  if (!(len > 0)) return true;
  n = n / len;
  for (const Vec3& q : pts)
    if (std::abs(dot(q - pts[0], n)) > eps) return false;
  return true;
}

}  // namespace

// ExtrudeCurve: returns the top curve; *body the swept surface (0 when no end point moved).
GeoResult<int> Model::extrude_curve_entity(int c, const ExtrudeSpec& spec, bool final, int* body) {
  *body = 0;
  const auto cit = curves_.find(std::abs(c));
  if (c == 0 || cit == curves_.end())
    return make_error(GeoErrorId::CannotActOnUnknown, EntityKind::Curve, {c}, {}, {}, {"extrude"});
  int beg = cit->second.begin, end = cit->second.end;
  if (c < 0) std::swap(beg, end);
  if (beg == end)
    note_compat(CompatNoteId::ExtrudeClosedCurve, {std::abs(c)});
  auto dup = duplicate({{1, c}});
  if (!dup) return dup.error();
  const int top = dup->front().tag;
  if (auto st = transform_by({{1, top}}, spec); !st) return st.error();
  Extrusion te;
  te.spec = spec;
  te.source = c;
  te.body = false;
  extrusions_[{1, top}] = te;
  int cb = 0, ce = 0;
  auto rb = extrude_point_entity(beg, spec, &cb);
  if (!rb) return rb.error();
  auto re = extrude_point_entity(end, spec, &ce);
  if (!re) return re.error();
  if (!cb && !ce) return top;
  // The boundary: the curve, the end's sweep, the top backwards, the beginning's sweep
  // backwards (a swept end on the axis drops out: a triangle).
  const int st = c > 0 ? top : -top;   // the copy runs as the curve's tag does, so as c
  std::vector<int> loop;
  if (!cb) loop = {c, ce, -st};
  else if (!ce) loop = {-st, -cb, c};
  else loop = {c, ce, -st, -cb};
  const int s = new_surface_tag();
  bump_max(2, s);
  ModelCurveLoop l;
  l.tag = std::numeric_limits<int>::max() - hidden_loop_tag_++;
  l.curves = loop;
  const int lt = l.tag;
  loops_.emplace(lt, std::move(l));
  ModelSurface ms;
  ms.tag = s;
  ms.loops = {lt};
  std::vector<Vec3> pts;
  for (int k : loop)
    for (int p : curves_.at(std::abs(k)).points) pts.push_back(vertices_.at(p).xyz);
  const double diag = bounding_box().diagonal();
  // A ruled surface (Gmsh's "Surface", meshed as a filling one) unless it is flat, where it
  // is the plane surface of its boundary.
  ms.filling = !coplanar(pts, 1e-9 * (diag > 0 ? diag : 1.0));
  surfaces_.emplace(s, std::move(ms));
  Extrusion se;
  se.spec = spec;
  se.source = c;
  se.begin_curve = cb;
  se.end_curve = ce;
  se.top = top;
  extrusions_[{2, s}] = se;
  *body = s;
  int result = top;
  if (final && options_.auto_coherence) {
    std::map<int, int> merged;
    coherence(&merged);
    for (auto& [key, ex] : extrusions_) {   // records follow the merged curves
      if (auto it = merged.find(ex.top); ex.top && it != merged.end()) ex.top = it->second;
      if (auto it = merged.find(ex.begin_curve); ex.begin_curve && it != merged.end()) ex.begin_curve = it->second;
      if (auto it = merged.find(ex.end_curve); ex.end_curve && it != merged.end()) ex.end_curve = it->second;
    }
    if (auto it = merged.find(top); it != merged.end()) result = it->second;
  }
  return result;
}

// ExtrudeSurface: returns the top surface; *volume the swept volume.
GeoResult<int> Model::extrude_surface_entity(int s, const ExtrudeSpec& spec, int* volume) {
  *volume = 0;
  const auto sit = surfaces_.find(std::abs(s));
  if (sit == surfaces_.end())
    return make_error(GeoErrorId::CannotActOnUnknown, EntityKind::Surface, {std::abs(s)}, {}, {}, {"extrude"});
  std::vector<int> generatrices;
  for (int l : sit->second.loops)
    for (int c : loops_.at(std::abs(l)).curves) generatrices.push_back(l > 0 ? c : -c);
  auto dup = duplicate({{2, std::abs(s)}});
  if (!dup) return dup.error();
  const int first_tag = dup->front().tag;
  {   // The copy's curves copy the source's, loop by loop (for the top's structured mesh).
    const ModelSurface& copy = surfaces_.at(first_tag);
    for (std::size_t i = 0; i < copy.loops.size() && i < sit->second.loops.size(); ++i) {
      const auto& cc = loops_.at(std::abs(copy.loops[i])).curves;
      const auto& sc = loops_.at(std::abs(sit->second.loops[i])).curves;
      for (std::size_t j = 0; j < cc.size() && j < sc.size(); ++j) {
        Extrusion ce;
        ce.spec = spec;
        ce.source = std::abs(sc[j]);
        ce.body = false;
        extrusions_[{1, std::abs(cc[j])}] = ce;
      }
    }
  }
  // Gmsh takes the volume's tag as if Geometry.OldNewReg were 0.
  const int v = max_tag_[3] + 1;
  bump_max(3, v);
  ModelVolume vol;
  vol.tag = v;
  vol.surfaces.push_back(-std::abs(s));
  std::vector<int> lateral;
  for (int c : generatrices) {
    int body = 0;
    auto r = extrude_curve_entity(c, spec, false, &body);
    if (!r) return r.error();
    // Gmsh 4.8.4's Boundary{Volume{}} lists the swept surfaces positive, also those swept
    // from a reversed curve (measured): they are built on the curve as the loop runs it.
    if (body) lateral.push_back(body);
  }
  if (auto st = transform_by({{2, first_tag}}, spec); !st) return st.error();
  // Renumbered last, as Gmsh does "for backward compatibility with the old numbering".
  ModelSurface top = surfaces_.at(first_tag);
  surfaces_.erase(first_tag);
  top.tag = new_surface_tag();
  bump_max(2, top.tag);
  const int tt = top.tag;
  surfaces_.emplace(tt, std::move(top));
  Extrusion te;
  te.spec = spec;
  te.source = s;
  te.body = false;
  extrusions_[{2, tt}] = te;
  vol.surfaces.push_back(tt);
  vol.surfaces.insert(vol.surfaces.end(), lateral.begin(), lateral.end());
  volumes_[v] = std::move(vol);
  Extrusion ve;
  ve.spec = spec;
  ve.source = s;
  extrusions_[{3, v}] = ve;
  *volume = v;
  if (options_.auto_coherence) {
    std::map<int, int> merged;
    coherence(&merged);
    for (auto& [key, ex] : extrusions_) {
      if (auto it = merged.find(ex.top); ex.top && it != merged.end()) ex.top = it->second;
      if (auto it = merged.find(ex.begin_curve); ex.begin_curve && it != merged.end()) ex.begin_curve = it->second;
      if (auto it = merged.find(ex.end_curve); ex.end_curve && it != merged.end()) ex.end_curve = it->second;
      if (key.first == 1 && !ex.body)
        if (auto it = merged.find(std::abs(ex.source)); it != merged.end())
          ex.source = ex.source > 0 ? it->second : -it->second;
    }
  }
  return tt;
}

GeoResult<std::vector<DimTag>> Model::extrude(const std::vector<DimTag>& entities, const ExtrudeSpec& spec) {
  touch();
  if (spec.kind != ExtrudeKind::Translate && !(norm(spec.axis) > 0))
    return make_error(GeoErrorId::ExtrusionAxisZero, EntityKind::None, {});
  std::vector<DimTag> out;
  const double diag = bounding_box().diagonal();
  const double eps = options_.tolerance * (diag > 0 ? diag : 1.0);
  for (const DimTag& e : entities) {
    if (e.dim == 0) {
      int body = 0;
      auto top = extrude_point_entity(std::abs(e.tag), spec, &body);
      if (!top) return top.error();
      int t = *top;
      if (body && options_.auto_coherence) {
        const Vec3 at = vertices_.at(t).xyz;
        std::map<int, int> merged;
        coherence(&merged);
        if (!vertices_.count(t))   // merged into the lowest tag at its place
          for (const auto& [tag, v] : vertices_)
            if (std::abs(v.xyz.x - at.x) <= eps && std::abs(v.xyz.y - at.y) <= eps && std::abs(v.xyz.z - at.z) <= eps) {
              t = tag;
              break;
            }
        if (merged.count(body)) body = 0;
      }
      out.push_back({0, t});
      if (body) out.push_back({1, body});
    } else if (e.dim == 1) {
      int body = 0;
      auto top = extrude_curve_entity(e.tag, spec, true, &body);
      if (!top) return top.error();
      out.push_back({1, *top});
      if (!body) continue;
      out.push_back({2, body});
      if (spec.return_lateral)
        for (int c : loops_.at(surfaces_.at(body).loops.front()).curves)
          // Gmsh compares |c| with the tag as written: extruding Curve{-1} lists curve 1 (as -1).
          if (std::abs(c) != e.tag && std::abs(c) != *top) out.push_back({1, c});
    } else if (e.dim == 2) {
      int vol = 0;
      auto top = extrude_surface_entity(e.tag, spec, &vol);
      if (!top) return top.error();
      out.push_back({2, *top});
      out.push_back({3, vol});
      if (spec.return_lateral)
        for (int s : volumes_.at(vol).surfaces)
          if (std::abs(s) != e.tag && std::abs(s) != *top) out.push_back({2, std::abs(s)});  // listed unsigned, as Gmsh
    } else {
      return make_error(GeoErrorId::CannotExtrudeVolume, EntityKind::Volume, {e.tag});
    }
  }
  return out;
}

}  // namespace sm::geo
