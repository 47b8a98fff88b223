// Model editing with Gmsh 4.8.4's semantics: Delete (skipped when in use, Recursive),
// Coherence, Duplicata, Translate/Rotate/Dilate/Symmetry (with AutoCoherence), Split Curve.
#include "geo/model.h"


#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>
#include <tuple>

namespace sm::geo {

namespace {

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

// ---- usage ----

Model::Usage Model::usage() const {
  Usage u;
  for (const auto& [t, c] : curves_)
    for (int p : c.points) ++u.point[p];
  for (const auto& [t, l] : loops_)
    for (int c : l.curves) ++u.curve[std::abs(c)];
  for (const auto& [t, s] : surfaces_) {
    for (int l : s.loops) ++u.loop[std::abs(l)];
    for (int p : s.embedded_points) ++u.point[p];
    for (int c : s.embedded_curves) ++u.curve[c];
  }
  return u;
}

namespace {

bool used(const std::map<int, int>& m, int tag) {
  auto it = m.find(tag);
  return it != m.end() && it->second > 0;
}

}  // namespace

// A curve blocks its deletion only on the boundary of a surface (a loop of an existing
// surface) or embedded in one: Gmsh 4.8.4 checks the surfaces' curves, not the curve
// loops, so `Delete{ Surface{1}; Curve{4}; }` deletes curve 4 once surface 1 is gone even
// though its curve loop still names it (Gmsh's tutorial t6 does this). A loop left naming
// a deleted curve fails only if a surface is later made of it, as in Gmsh.
bool Model::curve_on_surface(const Usage& u, int tag) const {
  for (const auto& [t, s] : surfaces_)
    if (contains(s.embedded_curves, tag)) return true;
  for (const auto& [t, l] : loops_)
    if (used(u.loop, t) && std::any_of(l.curves.begin(), l.curves.end(), [tag](int c) { return std::abs(c) == tag; }))
      return true;
  return false;
}

// Physical groups keep the tags of deleted entities, as Gmsh's do: an entity made again
// with the same tag is in the group again (tutorial t6 deletes surface 1 of t1, whose
// group "My surface" then holds the new surface 1). Meanwhile the group answers as Gmsh's
// does (Model::physical_entities: the existing members only; a group with none is neither
// listed nor written).
void Model::delete_point(int tag) {
  touch();
  vertices_.erase(tag);
  on_delete(0, tag);
}

void Model::delete_curve(int tag, bool recursive, Usage& u) {
  touch();
  const std::vector<int> pts = curves_.at(tag).points;
  curves_.erase(tag);
  on_delete(1, tag);
  for (int p : pts) --u.point[p];
  if (!recursive) return;
  for (int p : pts)
    if (vertices_.count(p) && !used(u.point, p)) delete_point(p);
}

void Model::delete_loop(int tag, bool recursive, Usage& u) {
  touch();
  const std::vector<int> cs = loops_.at(tag).curves;
  loops_.erase(tag);
  on_delete(kLoopSlot, tag);
  for (int c : cs) --u.curve[std::abs(c)];
  if (!recursive) return;
  for (int c : cs)
    if (curves_.count(std::abs(c)) && !used(u.curve, std::abs(c))) delete_curve(std::abs(c), true, u);
}

void Model::delete_surface(int tag, bool recursive, Usage& u) {
  touch();
  const ModelSurface s = surfaces_.at(tag);
  surfaces_.erase(tag);
  on_delete(2, tag);
  for (int l : s.loops) --u.loop[std::abs(l)];
  for (int c : s.embedded_curves) --u.curve[c];
  for (int p : s.embedded_points) --u.point[p];
  if (!recursive) return;
  for (int l : s.loops)
    if (loops_.count(std::abs(l)) && !used(u.loop, std::abs(l))) delete_loop(std::abs(l), true, u);
  for (int c : s.embedded_curves)
    if (curves_.count(c) && !used(u.curve, c)) delete_curve(c, true, u);
  for (int p : s.embedded_points)
    if (vertices_.count(p) && !used(u.point, p)) delete_point(p);
}

GeoStatus Model::remove(const std::vector<DimTag>& entities, bool recursive, std::vector<DimTag>* skipped) {
  touch();
  for (const DimTag& e : entities) {
    const int t = std::abs(e.tag);
    const bool exists = (e.dim == 0 && vertices_.count(t)) || (e.dim == 1 && curves_.count(t)) ||
                        (e.dim == 2 && surfaces_.count(t)) || (e.dim == 3 && volumes_.count(t));
    if (!exists)
      return make_error(GeoErrorId::CannotActOnUnknown, static_cast<EntityKind>(std::clamp(e.dim, 0, 3)), {e.tag}, {},
                        {}, {"delete"});
  }
  Usage u = usage();
  for (const DimTag& e : entities) {
    const int t = std::abs(e.tag);
    bool in_use = false;
    if (e.dim == 0 && vertices_.count(t)) {
      in_use = used(u.point, t);
      if (!in_use) delete_point(t);
    } else if (e.dim == 1 && curves_.count(t)) {
      in_use = curve_on_surface(u, t);
      if (!in_use) {
        // The curve loops that name it bound no surface (else it would be in use): they go
        // with it, so no loop names a missing curve. Gmsh keeps them dangling; a surface
        // made of one later fails there as here (an unknown curve loop, not curve).
        std::vector<int> dangling;
        for (const auto& [lt, l] : loops_)
          if (std::any_of(l.curves.begin(), l.curves.end(), [t](int c) { return std::abs(c) == t; }))
            dangling.push_back(lt);
        for (int lt : dangling) delete_loop(lt, false, u);
        delete_curve(t, recursive, u);
      }
    } else if (e.dim == 2 && surfaces_.count(t)) {
      delete_surface(t, recursive, u);
    } else if (e.dim == 3 && volumes_.count(t)) {   // geo/extrude.cpp: kept as an entity only
      const std::vector<int> bounding = volumes_.at(t).surfaces;
      volumes_.erase(t);
      extrusions_.erase({3, t});
      on_delete(3, t);
      if (recursive)
        for (int b : bounding)
          if (surfaces_.count(std::abs(b))) delete_surface(std::abs(b), true, u);
    }
    if (in_use && skipped) skipped->push_back(e);
  }
  return {};
}

// ---- coherence ----

int Model::coherence(std::map<int, int>* curves_merged) {
  touch();
  if (vertices_.empty()) return 0;
  const double diag = bounding_box().diagonal();
  const double eps = options_.tolerance * (diag > 0 ? diag : 1.0);
  // Points: union-find over pairs closer than eps in every coordinate (Gmsh's comparison),
  // found by a sweep in x; each cluster keeps its lowest tag.
  std::vector<const ModelVertex*> pts;
  pts.reserve(vertices_.size());
  for (const auto& [t, v] : vertices_) pts.push_back(&v);
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return pts[a]->xyz.x < pts[b]->xyz.x || (pts[a]->xyz.x == pts[b]->xyz.x && a < b);
  });
  std::vector<std::size_t> parent(pts.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Vec3 p = pts[order[a]]->xyz, q = pts[order[b]]->xyz;
      if (q.x - p.x > eps) break;
      if (std::abs(q.y - p.y) <= eps && std::abs(q.z - p.z) <= eps) {
        const std::size_t ra = find(order[a]), rb = find(order[b]);
        if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);   // pts is in tag order
      }
    }
  std::map<int, int> replace;   // merged point -> survivor
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::size_t r = find(i);
    if (r != i) replace[pts[i]->tag] = pts[r]->tag;
  }
  int merged = 0;
  std::vector<int> touched;
  for (auto& [t, c] : curves_) {
    bool hit = false;
    for (int& p : c.points)
      if (auto it = replace.find(p); it != replace.end()) {
        p = it->second;
        hit = true;
      }
    if (hit) {
      c.begin = c.points.front();
      c.end = c.points.back();
      touched.push_back(t);
    }
  }
  for (auto& [t, s] : surfaces_)
    for (int& p : s.embedded_points)
      if (auto it = replace.find(p); it != replace.end()) p = it->second;
  for (auto& [key, g] : physicals_)
    if (g.dim == 0)
      for (int& p : g.entities)
        if (auto it = replace.find(p); it != replace.end()) p = it->second;
  for (const auto& [from, to] : replace) {
    vertices_.erase(from);
    ++merged;
  }
  for (int t : touched) {
    auto shape = build_shape(curves_.at(t));
    if (shape) curves_.at(t).shape = std::move(*shape);
  }
  // Curves with the same kind, control points and plane: keep the lowest tag (curves_ is
  // visited in tag order, so the first one seen survives).
  using CurveKey = std::tuple<int, std::vector<int>, bool, double, double, double>;
  std::map<CurveKey, int> first_of;
  std::map<int, int> curve_replace;
  for (const auto& [t, c] : curves_) {
    if (c.discrete) continue;   // two discrete curves between the same points differ in between
    const Vec3 n = c.plane_normal.value_or(Vec3{});
    CurveKey key{static_cast<int>(c.kind), c.points, c.plane_normal.has_value(), n.x, n.y, n.z};
    auto [it, fresh] = first_of.emplace(std::move(key), t);
    if (!fresh) curve_replace[t] = it->second;
  }
  auto map_curve = [&](int& c) {
    if (auto it = curve_replace.find(std::abs(c)); it != curve_replace.end()) c = c > 0 ? it->second : -it->second;
  };
  for (auto& [t, l] : loops_)
    for (int& c : l.curves) map_curve(c);
  for (auto& [t, s] : surfaces_)
    for (int& c : s.embedded_curves) map_curve(c);
  for (auto& [key, g] : physicals_)
    if (g.dim == 1)
      for (int& c : g.entities) map_curve(c);
  if (curves_merged) *curves_merged = curve_replace;
  for (const auto& [from, to] : curve_replace) {
    curves_.erase(from);
    ++merged;
  }
  // Measured on gmsh 4.8.4: with Geometry.OldNewReg = 1 the next tags after a merge follow
  // the largest surviving tag; with OldNewReg = 0 the high-water marks stay.
  if (options_.old_new_reg) {
    // The point tags a Duplicata took for copies Gmsh makes and merges here count as merged.
    if (!replace.empty() || duplicate_took_spare_points_)
      max_tag_[0] = vertices_.empty() ? 0 : vertices_.rbegin()->first;
    if (!curve_replace.empty()) max_tag_[1] = curves_.empty() ? 0 : curves_.rbegin()->first;
  }
  duplicate_took_spare_points_ = false;
  return merged;
}

// ---- duplicata ----

GeoResult<std::vector<DimTag>> Model::duplicate(const std::vector<DimTag>& entities,
                                                std::vector<std::array<int, 3>>* copied) {
  touch();
  // Tags are taken in Gmsh 4.8.4's order (Geo/Geo.cpp, DuplicateCurve/DuplicateSurface):
  // a surface takes its tag before its curves; a curve takes its tag, then one new point
  // per control point and two more for its end points, every time, even for a point
  // already copied. Each source point has one copy here (the first one taken; the
  // others are tags Gmsh creates and its coherence merges away), and the copied
  // surface's curve loops, which Gmsh does not have, take tags that no next-tag
  // variable sees.
  std::map<int, int> point_copy;
  auto copy_point = [&](int p) {
    const int t = new_point_tag();
    bump_max(0, t);
    if (auto it = point_copy.find(p); it != point_copy.end()) {
      duplicate_took_spare_points_ = true;
      return it->second;
    }
    ModelVertex v = vertices_.at(p);
    v.tag = t;
    vertices_.emplace(t, v);
    point_copy[p] = t;
    return t;
  };
  auto copy_curve = [&](int signed_curve) {
    const int c = std::abs(signed_curve);
    ModelCurve n = curves_.at(c);
    n.tag = new_curve_tag();
    bump_max(1, n.tag);
    std::vector<int> copies(n.points.size());
    // A reversed curve is walked from its end, as Gmsh's reversed curve lists its points.
    for (std::size_t i = 0; i < n.points.size(); ++i) {
      const std::size_t k = signed_curve > 0 ? i : n.points.size() - 1 - i;
      copies[k] = copy_point(n.points[k]);
    }
    copy_point(n.begin);
    copy_point(n.end);
    n.points = std::move(copies);
    n.begin = n.points.front();
    n.end = n.points.back();
    const int tag = n.tag;
    curves_.emplace(tag, std::move(n));
    if (copied) copied->push_back({1, c, tag});
    return tag;
  };
  std::vector<DimTag> out;
  for (const DimTag& e : entities) {
    const int t = std::abs(e.tag);
    if (e.dim == 0 && vertices_.count(t)) {
      out.push_back({0, copy_point(t)});
    } else if (e.dim == 1 && curves_.count(t)) {
      out.push_back({1, copy_curve(e.tag)});   // a reversed curve's points are copied from its end
    } else if (e.dim == 2 && surfaces_.count(t)) {
      ModelSurface s = surfaces_.at(t);
      s.tag = new_surface_tag();
      bump_max(2, s.tag);
      std::map<int, int> curve_copy;   // a seam listed twice in a loop stays one curve
      for (int& l : s.loops) {
        ModelCurveLoop nl = loops_.at(std::abs(l));
        for (int& c : nl.curves) {
          auto [it, fresh] = curve_copy.emplace(std::abs(c), 0);
          if (fresh) it->second = copy_curve(c);
          c = c > 0 ? it->second : -it->second;
        }
        nl.tag = std::numeric_limits<int>::max() - hidden_loop_tag_++;
        const int lt = nl.tag;
        loops_.emplace(lt, std::move(nl));
        l = l > 0 ? lt : -lt;
      }
      // Gmsh's copy keeps no embedded entities.
      s.embedded_points.clear();
      s.embedded_curves.clear();
      const int st = s.tag;
      surfaces_.emplace(st, std::move(s));
      if (copied) copied->push_back({2, t, st});
      out.push_back({2, st});
    } else {
      note_compat(CompatNoteId::DuplicataOfMissing, {t},
                  e.dim == 0 ? "point" : e.dim == 1 ? "curve" : e.dim == 2 ? "surface" : "entity");
    }
  }
  return out;
}

// ---- transformations ----

std::vector<int> Model::points_of(const std::vector<DimTag>& entities) const {
  std::vector<int> pts;
  auto add_curve = [&](int c) {
    const ModelCurve& mc = curves_.at(std::abs(c));
    pts.insert(pts.end(), mc.points.begin(), mc.points.end());
  };
  for (const DimTag& e : entities) {
    const int t = std::abs(e.tag);
    if (e.dim == 0) {
      pts.push_back(t);
    } else if (e.dim == 1) {
      add_curve(t);
    } else if (e.dim == 2) {
      const ModelSurface& s = surfaces_.at(t);
      for (int l : s.loops)
        for (int c : loops_.at(std::abs(l)).curves) add_curve(c);
      for (int c : s.embedded_curves) add_curve(c);
      pts.insert(pts.end(), s.embedded_points.begin(), s.embedded_points.end());
    }
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

// m is a row-major 3x4 affine map [A | b]: x' = A x + b. Each point moves once, however many
// of the entities use it. A point on a surface geometry stays on it: its moved position is
// projected back (Gmsh moves the 3D position off the sphere and keeps the old (u,v)).
GeoStatus Model::transform_points(const std::vector<DimTag>& entities, const std::array<double, 12>& m) {
  touch();
  for (const DimTag& e : entities) {
    const int t = std::abs(e.tag);
    if ((e.dim == 0 && !vertices_.count(t)) || (e.dim == 1 && !curves_.count(t)) ||
        (e.dim == 2 && !surfaces_.count(t)) || e.dim < 0 || e.dim > 2)
      return make_error(GeoErrorId::CannotTransformUnknown,
                        e.dim >= 0 && e.dim <= 2 ? static_cast<EntityKind>(e.dim) : EntityKind::None, {e.tag}, {e.dim});
  }
  const std::vector<int> pts = points_of(entities);
  std::vector<ModelVertex> before;
  before.reserve(pts.size());
  for (int p : pts) before.push_back(vertices_.at(p));
  for (int p : pts) {
    ModelVertex& v = vertices_.at(p);
    const Vec3 x = v.xyz;
    v.xyz = {m[0] * x.x + m[1] * x.y + m[2] * x.z + m[3], m[4] * x.x + m[5] * x.y + m[6] * x.z + m[7],
             m[8] * x.x + m[9] * x.y + m[10] * x.z + m[11]};
    if (v.geometry) {
      const SurfaceGeometry& g = geometries_.at(v.geometry);
      v.uv = g.param(v.xyz);
      v.xyz = g.point(v.uv);
    }
  }
  GeoStatus s = rebuild_curves_using(pts);
  if (!s.ok()) {
    // An arc the map made invalid (a non-uniform Dilate of a circle, say): undo, so that a
    // failed statement leaves the model as it was.
    for (const ModelVertex& v : before) vertices_.at(v.tag) = v;
    rebuild_curves_using(pts);
    return s;
  }
  if (options_.auto_coherence) coherence();
  return s;
}

GeoStatus Model::translate(const std::vector<DimTag>& entities, Vec3 d) {
  return transform_points(entities, {1, 0, 0, d.x, 0, 1, 0, d.y, 0, 0, 1, d.z});
}

GeoStatus Model::rotate(const std::vector<DimTag>& entities, Vec3 axis, Vec3 p, double angle) {
  const double n = norm(axis);
  if (!(n > 0))
    return make_error(GeoErrorId::RotationAxisZero, EntityKind::None, {});
  const Vec3 k = axis / n;
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  // Rodrigues' rotation matrix about the unit axis k.
  const double r[9] = {c + k.x * k.x * t,       k.x * k.y * t - k.z * s, k.x * k.z * t + k.y * s,
                       k.y * k.x * t + k.z * s, c + k.y * k.y * t,       k.y * k.z * t - k.x * s,
                       k.z * k.x * t - k.y * s, k.z * k.y * t + k.x * s, c + k.z * k.z * t};
  // x' = p + R (x - p) = R x + (p - R p)
  const Vec3 rp{r[0] * p.x + r[1] * p.y + r[2] * p.z, r[3] * p.x + r[4] * p.y + r[5] * p.z,
                r[6] * p.x + r[7] * p.y + r[8] * p.z};
  const Vec3 b = p - rp;
  return transform_points(entities, {r[0], r[1], r[2], b.x, r[3], r[4], r[5], b.y, r[6], r[7], r[8], b.z});
}

GeoStatus Model::dilate(const std::vector<DimTag>& entities, Vec3 c, Vec3 f) {
  return transform_points(entities,
                          {f.x, 0, 0, c.x - f.x * c.x, 0, f.y, 0, c.y - f.y * c.y, 0, 0, f.z, c.z - f.z * c.z});
}

GeoStatus Model::symmetry(const std::vector<DimTag>& entities, double a, double b, double c, double d) {
  const double n2 = a * a + b * b + c * c;
  if (!(n2 > 0))
    return make_error(GeoErrorId::SymmetryPlaneZero, EntityKind::None, {});
  // x' = x - 2 (n.x + d) n / |n|^2
  const double k = 2.0 / n2;
  return transform_points(entities, {1 - k * a * a, -k * a * b, -k * a * c, -k * a * d,
                                     -k * b * a, 1 - k * b * b, -k * b * c, -k * b * d,
                                     -k * c * a, -k * c * b, 1 - k * c * c, -k * c * d});
}

// ---- split ----

GeoResult<std::vector<int>> Model::split_curve(int tag, const std::vector<int>& requested_points) {
  touch();
  auto it = curves_.find(tag);
  if (it == curves_.end())
    return make_error(GeoErrorId::CannotActOnUnknown, EntityKind::Curve, {tag}, {}, {}, {"split"});
  const ModelCurve old = it->second;
  if (old.kind == CurveKind::Circle || old.kind == CurveKind::Ellipse)
    return make_error(GeoErrorId::CannotSplitArc, EntityKind::Curve, {tag}, {}, {}, {to_string(old.kind)});
  std::vector<int> split_points;
  for (int p : requested_points) {
    if (contains(old.points, p)) {
      split_points.push_back(p);
    } else {
      note_compat(CompatNoteId::SplitAtOtherPoint, {tag, p});
    }
  }
  std::vector<int> pts = old.points;
  if (old.periodic() && pts.size() > 2 && !split_points.empty()) {
    // A closed curve starts at the first split point met after its start point, in the
    // curve's order (not the list's): Gmsh walks it from there round to that point again,
    // and its start point is then an ordinary split point (Geo/Geo.cpp, SplitCurve).
    std::size_t k = 1;
    while (k + 1 < pts.size() && !contains(split_points, pts[k])) ++k;
    pts.pop_back();
    std::rotate(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(k % pts.size()), pts.end());
    pts.push_back(pts.front());
  }
  std::vector<std::vector<int>> pieces(1);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pieces.back().push_back(pts[i]);
    if (i > 0 && i + 1 < pts.size() && contains(split_points, pts[i])) pieces.push_back({pts[i]});
  }
  // Build the pieces first so that a failure leaves the model unchanged.
  std::vector<ModelCurve> made;
  int next = new_curve_tag();
  for (const auto& piece : pieces) {
    ModelCurve c = old;
    c.tag = next++;
    c.points = piece;
    c.begin = piece.front();
    c.end = piece.back();
    auto shape = build_shape(c);
    if (!shape) return shape.error();
    c.shape = std::move(*shape);
    made.push_back(std::move(c));
  }
  curves_.erase(tag);
  on_delete(1, tag);
  std::vector<int> out;
  for (ModelCurve& c : made) {
    out.push_back(c.tag);
    bump_max(1, c.tag);
    curves_.emplace(c.tag, std::move(c));
  }
  auto replace_in = [&](std::vector<int>& list) {
    std::vector<int> r;
    for (int c : list) {
      if (std::abs(c) != tag) {
        r.push_back(c);
      } else if (c > 0) {
        r.insert(r.end(), out.begin(), out.end());
      } else {
        for (auto o = out.rbegin(); o != out.rend(); ++o) r.push_back(-*o);
      }
    }
    list = std::move(r);
  };
  for (auto& [t, l] : loops_) replace_in(l.curves);
  for (auto& [key, g] : physicals_)
    if (g.dim == 1) replace_in(g.entities);
  for (auto& [t, s] : surfaces_) replace_in(s.embedded_curves);
  return out;
}

}  // namespace sm::geo
