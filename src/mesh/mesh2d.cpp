// The face driver of 2D meshing (paper section 3.3): boundary nodes in the face's plane,
// Delaunay + edge recovery + hole removal, del2d/front2d refinement with the size converted
// to the plane (h / lambda on a PolarSphere; large faces in parts on threads, partition.h),
// Laplacian smoothing, 3D output.
#include "mesh/mesh2d.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "base/parallel.h"
#include "mesh/cdt.h"
#include "mesh/delaunay.h"
#include "mesh/frontal.h"
#include "mesh/meshadapt.h"
#include "mesh/modify/optimize.h"
#include "mesh/modify/smooth.h"
#include "mesh/partition.h"
#include "exact/predicates.h"
#include "mesh/refine.h"

namespace sm {
namespace {

constexpr std::uint32_t kNoLocal = 0xFFFFFFFFu;
// del2d's bound on circumradius / size. refine.h's 1/sqrt2 leaves edges short (square
// with holes, lc 0.03: median edge/size 0.92, 94.0% in [0.7, 1.4]); 0.76 centres them
// (0.98, 96.9%) but on the world ocean gives fewer well-shaped triangles than Gmsh (74.6%
// rho > 0.9 against 76.5%); 0.73 keeps both: square 95.6% in range, world 76.2% rho > 0.9
// and 95.4% in range (Gmsh: 91.5%).
constexpr double kDel2dRadiusLimit = 0.73;

// A face refined in one piece gets its own progress stage from this estimated size on
// (smaller ones refine in well under a tenth of a second).
constexpr std::uint64_t kNestedProgressTriangles = 65536;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The face's parameter plane: a PolarSphere's (u,v); for a lon/lat Sphere its Mercator
// plane (x, y) = (lon, asinh(tan lat)), conformal with factor r cos lat = r / cosh y, so
// the anisotropic metric J^T J = diag(r^2 cos^2 lat, r^2) of (lon, lat) becomes isotropic
// and the same refiners apply; or a Euclidean plane with an orthonormal basis (e1, e2)
// such that e1 x e2 is the outer loop's Newell normal, so the outer loop runs
// counter-clockwise in the plane. For a loop in z = const the basis is (x, +-y) and the
// coordinates are exact.
struct FacePlane {
  const geo::SurfaceGeometry* geom = nullptr;
  bool mercator = false;
  Vec3 o, e1, e2, n;
  bool ccw_is_outward = true;   // on a geometry: counter-clockwise triangles face outwards

  Vec2 to_plane(Vec3 x) const { return {dot(x - o, e1), dot(x - o, e2)}; }
  /// Plane point of surface parameters (u,v) (lon/lat in radians on a Sphere).
  Vec2 from_param(Vec2 uv) const { return mercator ? Vec2{uv.x, std::asinh(std::tan(uv.y))} : uv; }
  /// Surface parameters of a plane point.
  Vec2 to_param(Vec2 p) const { return mercator ? Vec2{p.x, std::atan(std::sinh(p.y))} : p; }
  Vec3 to_space(Vec2 p) const { return geom ? geom->point(to_param(p)) : o + p.x * e1 + p.y * e2; }
  double lambda(Vec2 p) const {
    if (!geom) return 1.0;
    if (const geo::PolarSphere* ps = geom->polar()) return ps->lambda(p);
    return geom->radius() / std::cosh(p.y);
  }
};

// What a face's target size depends on (the one definition, for the refiners and for the
// statistics after meshing): the size policy with the background field and, with
// Mesh.MeshSizeExtendFromBoundary, the extension of the boundary sizes into the face: the
// recovered boundary triangulation `bg` and per vertex the mean length of its boundary
// edges (inf: none). Outlives its FaceMesher when kept in Mesh2dResult::target_sizes.
struct FaceSizing {
  int tag = 0;
  double bbox = 0;
  field::SizePolicyOptions size;
  const field::SizeField* background = nullptr;
  FacePlane plane;
  TriangleStore bg;
  std::vector<double> bsize;
};

// Laplacian smoothing as smooth_laplacian (Jacobi passes, a move undone where it would
// invert or flatten a triangle, then Delaunay flips) but with vertices [0, fixed_count)
// pinned: embedded points are on no constrained edge and must not move.
void smooth_pinned(TriangleStore& m, std::uint32_t fixed_count, int passes) {
  const std::uint32_t nv = m.num_vertices();
  std::vector<Vec2> sum(nv), old(nv);
  std::vector<std::uint32_t> count(nv);
  for (int pass = 0; pass < passes; ++pass) {
    std::fill(sum.begin(), sum.end(), Vec2{0, 0});
    std::fill(count.begin(), count.end(), 0u);
    for (std::uint32_t s = 0; s < m.corner.size(); ++s) {
      if (!m.alive(tri_of(Side{s}))) continue;
      const std::uint32_t v = m.corner[s].value;
      sum[v] += m.pos(m.dest(Side{s}));
      ++count[v];
    }
    old = m.xy;
    for (std::uint32_t v = fixed_count; v < nv; ++v)
      if (count[v]) m.xy[v] = sum[v] / static_cast<double>(count[v]);
    // Undo moves around inverted or flat triangles until none is left (each round puts at
    // least one vertex back, so this ends).
    for (bool again = true; again;) {
      again = false;
      for (std::uint32_t t = 0; t < m.num_slots(); ++t) {
        if (!m.alive(TriId{t})) continue;
        const VertexId a = m.vertex(TriId{t}, 0), b = m.vertex(TriId{t}, 1), c = m.vertex(TriId{t}, 2);
        if (orient2d(m.pos(a), m.pos(b), m.pos(c)) == Sign::Positive) continue;
        for (VertexId v : {a, b, c})
          if (m.xy[v.value] != old[v.value]) m.xy[v.value] = old[v.value], again = true;
      }
    }
    make_delaunay(m);
  }
}

// One closed chain of global nodes (first not repeated) with the curve of each edge.
struct Chain {
  std::vector<std::uint32_t> nodes;
  std::vector<int> edge_curve;
};

class FaceMesher {
 public:
  /// local_of: global node -> local vertex, all kNoLocal; left so again on return.
  FaceMesher(const geo::Model& model, ModelMesh& mesh, const Mesh2dOptions& opt, double bbox, Mesh2dResult& res,
             std::vector<std::uint32_t>& local_of)
      : model_(model), mesh_(mesh), opt_(opt), bbox_(bbox), res_(res), local_of_(local_of) {}
  ~FaceMesher() {
    for (std::uint32_t node : global_)
      if (node < local_of_.size()) local_of_[node] = kNoLocal;
  }
  bool run(const geo::ModelSurface& s);
  /// Only up to the element budget: run() stops once the estimate is checked.
  void estimate_only() { estimate_only_ = true; }

 private:
  bool fail(std::string msg, std::optional<Vec3> where = std::nullopt);
  /// "lon X, lat Y" of a point of the face (on a geometry), else "(x, y, z)".
  std::string where_text(Vec3 p) const;
  bool collect_loops(const geo::ModelSurface& s);
  bool make_plane();
  std::uint32_t local(std::uint32_t node);
  Vec2 node_plane(std::uint32_t node) const;
  Vec2 node_param(std::uint32_t node) const;   // on a geometry: the node's (u,v)
  bool refine(const std::function<void(std::span<const Vec2>, std::span<double>)>& size_at, std::uint64_t estimate);

  const geo::Model& model_;
  ModelMesh& mesh_;
  const Mesh2dOptions& opt_;
  double bbox_;
  Mesh2dResult& res_;
  int tag_ = 0;
  FacePlane plane_;
  std::vector<Chain> chains_;                 // [0] outer, then holes
  std::vector<std::uint32_t> emb_points_;     // global nodes
  std::vector<Chain> emb_curves_;             // open chains (edge i joins nodes i, i+1)
  std::vector<std::uint32_t> global_;         // local vertex -> global node
  std::vector<std::uint32_t>& local_of_;      // global node -> local vertex (shared scratch)
  TriangleStore m_;
  // Set once the boundary is recovered (the plane and the boundary sizes are final then).
  std::shared_ptr<FaceSizing> sizing_ = std::make_shared<FaceSizing>();
  std::atomic<std::uint64_t> size_evaluations_{0};
  bool estimate_only_ = false;
};

// The target size at batches of points of the face's plane: the size policy with the
// background field and the extension from the boundary (FaceSizing). Holds its own
// scratch and walk hint, so each part of a partitioned face gets its own and none writes
// another's; the face data it reads is not modified while it lives.
class PlaneSizes {
 public:
  /// evaluations: counts the points evaluated (shared by the parts), may be null.
  explicit PlaneSizes(const FaceSizing& f, std::atomic<std::uint64_t>* evaluations = nullptr)
      : f_(f), evaluations_(evaluations) {}
  /// h[i] = the size in the plane at p[i]: the size on the surface divided by lambda.
  void operator()(std::span<const Vec2> p, std::span<double> h);
  /// h[i] = the size on the surface (3D lengths) at p[i].
  void on_surface(std::span<const Vec2> p, std::span<double> h);

 private:
  std::optional<double> boundary_size(Vec2 p);

  const FaceSizing& f_;
  std::atomic<std::uint64_t>* evaluations_;
  TriId hint_;
  std::uint32_t walk_turn_ = 0;
  std::vector<Vec3> pts3_;
  std::vector<double> field_;
};

// The face's target size at 3D points for the statistics: each point is taken to the
// face's plane (radially onto a sphere first) and given PlaneSizes::on_surface there.
SizeAt3 target_size_fn(std::shared_ptr<const FaceSizing> sizing) {
  auto sizes = std::make_shared<PlaneSizes>(*sizing);
  auto plane_pts = std::make_shared<std::vector<Vec2>>();
  return [sizing, sizes, plane_pts](std::span<const Vec3> x, std::span<double> h) {
    const FacePlane& fp = sizing->plane;
    plane_pts->resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      (*plane_pts)[i] = fp.geom ? fp.from_param(fp.geom->param(x[i])) : fp.to_plane(x[i]);
    sizes->on_surface(*plane_pts, h);
  };
}

bool FaceMesher::fail(std::string msg, std::optional<Vec3> where) {
  res_.error.surface = tag_;
  res_.error.message = fmt::format("surface {}: {}", tag_, msg);
  if (where) {
    res_.error.xyz = *where;
    if (plane_.geom) {
      res_.error.has_lonlat = true;
      if (plane_.geom->polar()) {
        res_.error.where = plane_.geom->polar()->to_lonlat(*where);
      } else {
        const Vec2 ll = plane_.geom->param(*where);
        res_.error.where = {ll.x * geo::kRadToDeg, ll.y * geo::kRadToDeg};
      }
      res_.error.message += fmt::format(" near lon {:.6f}, lat {:.6f}", res_.error.where.lon, res_.error.where.lat);
    } else {
      res_.error.message += fmt::format(" near ({}, {}, {})", where->x, where->y, where->z);
    }
  }
  return false;
}

std::string FaceMesher::where_text(Vec3 p) const {
  if (!plane_.geom) return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z);
  geo::LonLat ll;
  if (plane_.geom->polar()) {
    ll = plane_.geom->polar()->to_lonlat(p);
  } else {
    const Vec2 uv = plane_.geom->param(p);
    ll = {uv.x * geo::kRadToDeg, uv.y * geo::kRadToDeg};
  }
  return fmt::format("lon {:.4f}, lat {:.4f}", ll.lon, ll.lat);
}

bool FaceMesher::collect_loops(const geo::ModelSurface& s) {
  // Islands below the mesh size (hole chains of fewer than 3 mesh edges): one warning
  // for the face, naming the largest, rather than one line per island.
  struct Island {
    int loop;
    double span;   // distance between its nodes: a lower bound of its size
    Vec3 at;
  };
  std::vector<Island> islands;
  for (std::size_t li = 0; li < s.loops.size(); ++li) {
    const geo::ModelCurveLoop* loop = model_.curve_loop(std::abs(s.loops[li]));
    if (!loop) return fail(fmt::format("curve loop {} does not exist", std::abs(s.loops[li])));
    std::vector<int> curves = loop->curves;
    if (s.loops[li] < 0) {
      std::reverse(curves.begin(), curves.end());
      for (int& c : curves) c = -c;
    }
    // A loop may hold several closed chains (Gmsh's subloops): a chain ends when it
    // returns to its first node.
    Chain ch;
    for (int sc : curves) {
      const auto it = mesh_.curves.find(std::abs(sc));
      if (it == mesh_.curves.end()) return fail(fmt::format("curve {} has no 1D mesh", std::abs(sc)));
      std::vector<std::uint32_t> nodes = it->second.nodes;
      if (sc < 0) std::reverse(nodes.begin(), nodes.end());
      if (!ch.nodes.empty() && ch.nodes.back() != nodes.front())
        return fail(fmt::format("curve loop {} is not connected at curve {}", loop->tag, sc));
      for (std::size_t k = ch.nodes.empty() ? 0 : 1; k < nodes.size(); ++k) ch.nodes.push_back(nodes[k]);
      ch.edge_curve.insert(ch.edge_curve.end(), nodes.size() - 1, std::abs(sc));
      if (ch.nodes.size() > 1 && ch.nodes.back() == ch.nodes.front()) {
        ch.nodes.pop_back();
        if (ch.nodes.size() < 3 && (li > 0 || !chains_.empty())) {
          // An island below the mesh size meshed as two edges encloses nothing: left out
          // (Gmsh does the same).
          const Vec3 a = mesh_.nodes[ch.nodes.front()].xyz, b = mesh_.nodes[ch.nodes.back()].xyz;
          islands.push_back({loop->tag, norm(b - a), (a + b) * 0.5});
        } else if (ch.nodes.size() < 3) {
          return fail(fmt::format("curve loop {} has fewer than 3 boundary nodes", loop->tag),
                      mesh_.nodes[ch.nodes.front()].xyz);
        } else {
          chains_.push_back(std::move(ch));
        }
        ch = Chain{};
      }
    }
    if (!ch.nodes.empty()) return fail(fmt::format("curve loop {} does not close", loop->tag));
  }
  if (!islands.empty()) {
    // The first island of the largest span: deterministic for equal spans.
    std::size_t big = 0;
    for (std::size_t i = 1; i < islands.size(); ++i)
      if (islands[i].span > islands[big].span) big = i;
    constexpr std::size_t kListed = 8;
    std::string loops;
    for (std::size_t i = 0; i < std::min(islands.size(), kListed); ++i)
      loops += fmt::format("{}{}", i ? ", " : "", islands[i].loop);
    if (islands.size() > kListed) loops += fmt::format(" and {} more", islands.size() - kListed);
    const bool one = islands.size() == 1;
    res_.warnings.push_back(fmt::format(
        "surface {}: {} island{} smaller than the mesh size {} left out ({} closed curve{} got fewer than 3 mesh "
        "edges; {}near {}): hole loop{} {}",
        tag_, islands.size(), one ? "" : "s", one ? "is" : "are", one ? "its" : "their", one ? "" : "s",
        one ? "" : "largest ", where_text(islands[big].at), one ? "" : "s", loops));
  }
  if (chains_.empty()) return fail("no boundary loop");
  for (int p : s.embedded_points) {
    const auto it = mesh_.vertex_node.find(p);
    if (it == mesh_.vertex_node.end()) return fail(fmt::format("embedded point {} has no node", p));
    emb_points_.push_back(it->second);
  }
  for (int c : s.embedded_curves) {
    const auto it = mesh_.curves.find(c);
    if (it == mesh_.curves.end()) return fail(fmt::format("embedded curve {} has no 1D mesh", c));
    Chain ch;
    ch.nodes = it->second.nodes;
    ch.edge_curve.assign(ch.nodes.size() - 1, c);
    emb_curves_.push_back(std::move(ch));
  }
  return true;
}

bool FaceMesher::make_plane() {
  if (plane_.geom) {
    plane_.mercator = plane_.geom->lonlat() != nullptr;
    Vec2 uv{0, 0};
    for (const auto* group : {&chains_, &emb_curves_})
      for (const Chain& ch : *group)
        for (std::uint32_t v : ch.nodes) {
          uv = node_param(v);
          if (plane_.mercator && !(std::abs(uv.y) < 0.5 * geo::kPi - 1e-9))
            return fail("a lon/lat Sphere face cannot reach a pole (its parametrisation is singular there); "
                        "use a PolarSphere",
                        mesh_.nodes[v].xyz);
        }
    uv = node_param(chains_[0].nodes[0]);
    Vec3 du, dv;
    plane_.geom->tangents(uv, du, dv);
    // Mercator keeps the orientation of (lon, lat): dy/dlat = 1 / cos lat > 0.
    plane_.ccw_is_outward = dot(cross(du, dv), plane_.geom->point(uv) - plane_.geom->centre()) > 0;
    return true;
  }
  // Newell's normal of the outer loop and its centroid.
  Vec3 n{0, 0, 0}, c{0, 0, 0};
  const std::vector<std::uint32_t>& L = chains_[0].nodes;
  for (std::size_t i = 0; i < L.size(); ++i) {
    const Vec3 a = mesh_.nodes[L[i]].xyz, b = mesh_.nodes[L[(i + 1) % L.size()]].xyz;
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    c = c + a;
  }
  c = c / static_cast<double>(L.size());
  const double nn = norm(n);
  if (!(nn > 0)) return fail("the outer loop encloses no area", mesh_.nodes[L[0]].xyz);
  n = n / nn;
  if (n.x == 0 && n.y == 0) {
    plane_.o = {0, 0, c.z};
    plane_.e1 = {1, 0, 0};
    plane_.e2 = {0, n.z > 0 ? 1.0 : -1.0, 0};
    plane_.n = {0, 0, n.z > 0 ? 1.0 : -1.0};
    plane_.o.z = mesh_.nodes[L[0]].xyz.z;
  } else {
    const Vec3 axis = std::abs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    plane_.e1 = cross(axis, n);
    plane_.e1 = plane_.e1 / norm(plane_.e1);
    plane_.e2 = cross(n, plane_.e1);
    plane_.o = c;
    plane_.n = n;
  }
  // Every boundary node must lie in that plane (Gmsh's Plane Surface is planar).
  const double tol = std::max(model_.options().tolerance * bbox_, 1e-12 * bbox_);
  auto check = [&](std::uint32_t node) {
    const Vec3 x = mesh_.nodes[node].xyz;
    return std::abs(dot(x - plane_.o, plane_.n)) <= tol;
  };
  for (const auto* group : {&chains_, &emb_curves_})
    for (const Chain& ch : *group)
      for (std::uint32_t v : ch.nodes)
        if (!check(v)) return fail("the boundary is not planar", mesh_.nodes[v].xyz);
  for (std::uint32_t v : emb_points_)
    if (!check(v)) return fail("an embedded point is not in the surface's plane", mesh_.nodes[v].xyz);
  return true;
}

Vec2 FaceMesher::node_param(std::uint32_t node) const {
  const MeshNode& n = mesh_.nodes[node];
  return n.has_uv ? n.uv : plane_.geom->param(n.xyz);
}

Vec2 FaceMesher::node_plane(std::uint32_t node) const {
  if (plane_.geom) return plane_.from_param(node_param(node));
  return plane_.to_plane(mesh_.nodes[node].xyz);
}

std::uint32_t FaceMesher::local(std::uint32_t node) {
  if (local_of_[node] == kNoLocal) {
    local_of_[node] = static_cast<std::uint32_t>(global_.size());
    global_.push_back(node);
    m_.add_vertex(node_plane(node));
  }
  return local_of_[node];
}

// Barycentric interpolation of the boundary sizes in the recovered boundary
// triangulation: a visibility walk from the last hit that stops at the domain's boundary
// (the point is then clamped to the last triangle).
std::optional<double> PlaneSizes::boundary_size(Vec2 p) {
  const TriangleStore& bg = f_.bg;
  const std::vector<double>& bsize = f_.bsize;
  if (!hint_.valid() || !bg.alive(hint_)) {
    hint_ = TriId{};
    for (std::uint32_t t = 0; t < bg.num_slots(); ++t)
      if (bg.alive(TriId{t})) {
        hint_ = TriId{t};
        break;
      }
    if (!hint_.valid()) return std::nullopt;
  }
  TriId t = hint_;
  const std::uint32_t cap = 4 * bg.num_slots() + 16;
  for (std::uint32_t step = 0; step < cap; ++step) {
    bool moved = false;
    walk_turn_ = (walk_turn_ + 1) % 3;
    for (std::uint32_t k = 0; k < 3 && !moved; ++k) {
      const Side s = side_of(t, (walk_turn_ + k) % 3);
      if (orient2d(bg.pos(bg.org(s)), bg.pos(bg.dest(s)), p) != Sign::Negative) continue;
      const Side o = bg.twin[s.value];
      if (!o.valid()) continue;   // beyond the boundary: try another edge, else stop here
      t = tri_of(o);
      moved = true;
    }
    if (!moved) break;
  }
  hint_ = t;
  const Vec2 a = bg.pos(bg.vertex(t, 0)), b = bg.pos(bg.vertex(t, 1)), c = bg.pos(bg.vertex(t, 2));
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  double w[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  if (area > 0) {
    w[0] = ((b.x - p.x) * (c.y - p.y) - (b.y - p.y) * (c.x - p.x)) / area;
    w[1] = ((c.x - p.x) * (a.y - p.y) - (c.y - p.y) * (a.x - p.x)) / area;
    w[2] = ((a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x)) / area;
  }
  double sum_w = 0, sum = 0;
  for (std::uint32_t e = 0; e < 3; ++e) {
    const double h = bsize[bg.vertex(t, e).value];
    const double wi = std::max(0.0, w[e]);
    if (!std::isfinite(h)) continue;
    sum_w += wi;
    sum += wi * h;
  }
  if (sum_w > 0) return sum / sum_w;
  double lo = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = 0; e < 3; ++e) lo = std::min(lo, bsize[bg.vertex(t, e).value]);
  return std::isfinite(lo) ? std::optional<double>(lo) : std::nullopt;
}

void PlaneSizes::on_surface(std::span<const Vec2> p, std::span<double> h) {
  pts3_.resize(p.size());
  field_.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) pts3_[i] = f_.plane.to_space(p[i]);
  if (f_.background) f_.background->eval_on(field::EntityRef{2, f_.tag}, pts3_, field_);
  field::SizeQuery q;
  q.bbox_diag = f_.bbox;
  q.entity_dim = 2;
  const bool extend = f_.size.extend_from_boundary != 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (f_.background) q.background = field_[i];
    double size = field::final_size(f_.size, q).size;
    if (extend) size = field::surface_target(f_.size, size, boundary_size(p[i]));
    h[i] = size;
  }
  if (evaluations_) evaluations_->fetch_add(p.size(), std::memory_order_relaxed);
}

void PlaneSizes::operator()(std::span<const Vec2> p, std::span<double> h) {
  on_surface(p, h);
  for (std::size_t i = 0; i < p.size(); ++i) h[i] /= f_.plane.lambda(p[i]);
}

// del2d or front2d on the face: in one piece, or in parts (partition.h) when the estimated
// triangle count reaches opt_.partition.min_triangles. The part count depends on the
// estimate only, so the mesh is the same for every thread count.
bool FaceMesher::refine(const std::function<void(std::span<const Vec2>, std::span<double>)>& size_at,
                        std::uint64_t estimate) {
  RefineOptions ro;
  ro.max_vertices = opt_.max_vertices_per_face;
  ro.size_at = size_at;
  const bool frontal = opt_.algorithm == Mesh2dAlgorithm::Frontal;
  if (opt_.radius_limit > 0) ro.radius_limit = opt_.radius_limit;
  else if (!frontal) ro.radius_limit = kDel2dRadiusLimit;
  const bool partitioning = opt_.partition.min_triangles > 0;
  if (partitioning && estimate >= opt_.partition.min_triangles) {
    ro.size_at = nullptr;
    const auto make_size = [this]() -> PlaneSizeFn {
      auto sizes = std::make_shared<PlaneSizes>(*sizing_, &size_evaluations_);
      return [sizes](std::span<const Vec2> p, std::span<double> h) { (*sizes)(p, h); };
    };
    // "2D refine", nested in "2D", one unit per part: a large face is one unit of "2D"
    // that would otherwise show nothing for seconds. Reported from this thread only.
    bool nested = false;
    const auto on_parts = [this, &nested](std::uint32_t done, std::uint32_t parts) {
      if (!opt_.progress) return;
      if (!nested) progress_begin(opt_.progress, "2D refine", parts), nested = true;
      progress_update(opt_.progress, done);
    };
    const PartitionResult pr = refine_partitioned(m_, ro, frontal ? PartRefiner::Frontal : PartRefiner::Del2d,
                                                  make_size, opt_.partition, resolve_thread_count(opt_.threads),
                                                  on_parts);
    if (nested) progress_end(opt_.progress);
    res_.stats.inserted += pr.stats.refine.inserted;
    res_.stats.rejected += pr.stats.refine.rejected;
    res_.stats.parts += pr.stats.parts;
    res_.stats.estimated_triangles += pr.stats.estimate;
    ++res_.stats.partitioned_faces;
    if (!pr.ok()) return fail("refinement failed: " + pr.error);
    // Parts are Delaunay inside; smoothing ends with flips that make the seams so too.
    if (opt_.smoothing <= 0) make_delaunay(m_);
    return true;
  }
  // A large face in one piece: "2D refine" nested in "2D" in estimated triangles, told
  // by the refiner every 64k insertions (done is capped at the estimate, which it may pass).
  const bool nested = opt_.progress && estimate >= kNestedProgressTriangles;
  if (nested) {
    progress_begin(opt_.progress, "2D refine", estimate);
    ro.on_progress = [this, estimate](std::uint64_t triangles) {
      progress_update(opt_.progress, std::min(triangles, estimate));
    };
  }
  RefineResult rf;
  if (frontal) rf = refine_front2d(m_, ro);
  else rf = refine_del2d(m_, ro);
  if (nested) {
    if (rf.ok()) progress_update(opt_.progress, estimate);
    progress_end(opt_.progress);
  }
  res_.stats.inserted += rf.stats.inserted;
  res_.stats.rejected += rf.stats.rejected;
  if (!rf.ok()) return fail("refinement failed: " + rf.error);
  return true;
}

bool FaceMesher::run(const geo::ModelSurface& s) {
  tag_ = s.tag;
  if (s.filling) return fail("transfinite (filling) surfaces are not meshed by the 2D mesher yet");
  plane_.geom = s.geometry ? model_.geometry(s.geometry) : nullptr;
  if (s.geometry && !plane_.geom) return fail(fmt::format("surface geometry {} does not exist", s.geometry));
  auto t0 = std::chrono::steady_clock::now();
  if (!collect_loops(s) || !make_plane()) return false;

  // Local vertices: loops, embedded curves, embedded points (first occurrence order).
  // The scratch map is shared by all faces and reset entry by entry (O(face) per face).
  local_of_.resize(mesh_.nodes.size(), kNoLocal);
  std::vector<Loop> loops;
  std::vector<Edge> edges;
  std::vector<int> edge_curve;
  for (std::size_t ci = 0; ci < chains_.size(); ++ci) {
    Loop L;
    L.hole = ci > 0;
    for (std::uint32_t node : chains_[ci].nodes) L.v.push_back(VertexId{local(node)});
    for (std::size_t k = 0; k < L.v.size(); ++k) {
      edges.push_back({L.v[k], L.v[(k + 1) % L.v.size()]});
      edge_curve.push_back(chains_[ci].edge_curve[k]);
    }
    loops.push_back(std::move(L));
  }
  for (const Chain& ch : emb_curves_)
    for (std::size_t k = 0; k + 1 < ch.nodes.size(); ++k) {
      edges.push_back({VertexId{local(ch.nodes[k])}, VertexId{local(ch.nodes[k + 1])}});
      edge_curve.push_back(ch.edge_curve[k]);
    }
  for (std::uint32_t node : emb_points_) local(node);
  const std::uint32_t fixed_count = m_.num_vertices();

  const DelaunayResult dr = delaunay(m_);
  if (!dr.ok()) return fail("Delaunay of the boundary nodes failed: " + dr.error);
  if (!dr.duplicates.empty()) {
    const std::uint32_t a = global_[dr.duplicates[0].dup.value], b = global_[dr.duplicates[0].kept.value];
    return fail(fmt::format("two distinct boundary nodes ({} and {}) at the same place", a, b), mesh_.nodes[a].xyz);
  }
  const PlanarGeometry g{&m_.xy};
  const RecoverResult rr = recover_edges(m_, g, edges);
  if (!rr.ok()) return fail("boundary recovery failed: " + rr.error);
  if (!rr.crossings.empty()) {
    const EdgeCrossing& x = rr.crossings[0];
    const Edge e = edges[x.edge];
    const int other = x.other != kNoEdge ? edge_curve[x.other] : 0;
    return fail(fmt::format("boundary edges of curves {} and {} cross", edge_curve[x.edge], other),
                mesh_.nodes[global_[e.first.value]].xyz);
  }
  if (!rr.touching.empty()) {
    const VertexOnEdge& x = rr.touching[0];
    return fail(fmt::format("a boundary node lies on an edge of curve {}", edge_curve[x.edge]),
                mesh_.nodes[global_[x.v.value]].xyz);
  }
  const DomainResult dom = remove_outside(m_, g, loops);
  if (!dom.ok()) return fail("hole removal failed: " + dom.error);

  FaceSizing& sz = *sizing_;
  sz.tag = tag_;
  sz.bbox = bbox_;
  sz.size = opt_.size;
  sz.background = opt_.background;
  sz.plane = plane_;
  if (opt_.size.extend_from_boundary != 0) {
    sz.bg = m_;
    std::vector<double>& bsize = sz.bsize;
    bsize.assign(fixed_count, 0.0);
    std::vector<std::uint32_t> count(fixed_count, 0);
    // A coarse boundary (the element budget's) carries the 1D sizes at its nodes: those,
    // not its long edges, are what the real boundary would extend.
    std::vector<double> node_h;
    if (estimate_only_) {
      node_h.assign(mesh_.nodes.size(), 0.0);
      for (const auto& [ct, cm] : mesh_.curves)
        for (std::size_t k = 0; k < cm.h.size() && k < cm.nodes.size(); ++k) node_h[cm.nodes[k]] = cm.h[k];
    }
    auto edge_length = [&](std::uint32_t ga, std::uint32_t gb) {
      if (estimate_only_ && node_h[ga] > 0 && node_h[gb] > 0) return 0.5 * (node_h[ga] + node_h[gb]);
      return norm(mesh_.nodes[ga].xyz - mesh_.nodes[gb].xyz);
    };
    for (const Edge& e : edges) {
      const double len = edge_length(global_[e.first.value], global_[e.second.value]);
      bsize[e.first.value] += len, bsize[e.second.value] += len;
      ++count[e.first.value], ++count[e.second.value];
    }
    for (std::uint32_t v = 0; v < fixed_count; ++v) {
      bsize[v] = count[v] ? bsize[v] / count[v] : std::numeric_limits<double>::infinity();
      if (!count[v]) {
        // An embedded point with a prescribed size keeps it.
        for (const auto& [vt, node] : mesh_.vertex_node)
          if (node == global_[v]) {
            const geo::ModelVertex* mv = model_.vertex(vt);
            if (mv && opt_.size.from_points && mv->lc < geo::kMaxLc) bsize[v] = mv->lc * opt_.size.factor;
            break;
          }
      }
    }
  }
  // The estimated triangle count (run() made it for the budget, the partitioning or the
  // progress display) uses its own evaluator: the refiner's walk hints stay as without
  // it. It is counted in the size evaluations only when partitioning uses it.
  const bool partitioning = opt_.partition.min_triangles > 0 && opt_.algorithm != Mesh2dAlgorithm::MeshAdapt;
  std::uint64_t estimate = 0;
  if (partitioning || opt_.progress || opt_.max_elements > 0) {
    PlaneSizes estimate_sizes(*sizing_, partitioning ? &size_evaluations_ : nullptr);
    const PlaneSizeFn estimate_at = [&estimate_sizes](std::span<const Vec2> p, std::span<double> h) {
      estimate_sizes(p, h);
    };
    estimate = estimate_triangles(m_, estimate_at);
    if (opt_.max_elements > 0 && static_cast<double>(estimate) > opt_.max_elements) {
      fail(fmt::format("it would get about {:.1e} triangles, over the limit of {:g}", static_cast<double>(estimate),
                       opt_.max_elements));
      res_.error.kind = Mesh2dErrorKind::LimitExceeded;
      res_.error.count = static_cast<double>(estimate);
      res_.error.limit = opt_.max_elements;
      return false;
    }
  }
  res_.stats.seconds_boundary += seconds_since(t0);
  if (estimate_only_) return true;

  t0 = std::chrono::steady_clock::now();
  PlaneSizes sizes(*sizing_, &size_evaluations_);
  const auto size_at = [&sizes](std::span<const Vec2> p, std::span<double> h) { sizes(p, h); };
  bool smoothed = false;
  if (opt_.algorithm == Mesh2dAlgorithm::MeshAdapt) {
    // Meshadapt is serial: its rounds of split/collapse/swap act on the whole face.
    MeshAdaptOptions mo;
    mo.size_at = size_at;
    mo.smoothing_passes = std::max(0, opt_.smoothing);
    mo.max_vertices = opt_.max_vertices_per_face;
    const MeshAdaptResult ma = mesh_adapt(m_, mo);
    if (!ma.ok()) return fail("meshadapt failed: " + ma.error);
    res_.stats.inserted += ma.stats.splits;
    smoothed = true;   // meshadapt smooths in each round
  } else if (!refine(size_at, estimate)) {
    return false;
  }
  res_.stats.size_evaluations += size_evaluations_.exchange(0);
  res_.stats.seconds_refine += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  if (opt_.smoothing > 0 && !smoothed) {
    // smooth_laplacian keeps vertices of constrained edges in place; an isolated
    // embedded point is not on one and would move: such faces pin every input vertex.
    if (emb_points_.empty()) smooth_laplacian(m_, opt_.smoothing, resolve_thread_count(opt_.threads));
    else smooth_pinned(m_, fixed_count, opt_.smoothing);
  }
  res_.stats.seconds_smooth += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  if (opt_.smoothing > 0 && opt_.quality_pass) {
    OptimizeOptions oo;
    if (opt_.algorithm == Mesh2dAlgorithm::Del2d || opt_.algorithm == Mesh2dAlgorithm::Automatic) {
      // del2d's many triangles just under 0.9 would cost ~4x the refinement to lift
      // (square: 87% -> 99% rho > 0.9); work on the bad ones only (~20% of refinement).
      oo.threshold = 0.75;
      oo.sacrifice_below = 0.7;
      oo.max_share_loss = 1e-4;
    }
    optimize_quality(m_, fixed_count, oo);
  }
  res_.stats.seconds_optimize += seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  SurfaceMesh sm_out;
  sm_out.tag = tag_;
  const std::uint32_t nv = m_.num_vertices();
  global_.resize(nv);
  for (std::uint32_t v = fixed_count; v < nv; ++v) {
    const Vec2 p = m_.xy[v];
    global_[v] = plane_.geom ? mesh_.add_node(plane_.to_space(p), plane_.to_param(p)) : mesh_.add_node(plane_.to_space(p));
    sm_out.interior_nodes.push_back(global_[v]);
  }
  const bool flip = plane_.geom && !plane_.ccw_is_outward;
  sm_out.triangles.reserve(m_.num_triangles());
  for (std::uint32_t t = 0; t < m_.num_slots(); ++t) {
    if (!m_.alive(TriId{t})) continue;
    const std::uint32_t a = global_[m_.vertex(TriId{t}, 0).value], b = global_[m_.vertex(TriId{t}, 1).value],
                        c = global_[m_.vertex(TriId{t}, 2).value];
    sm_out.triangles.push_back(flip ? std::array<std::uint32_t, 3>{a, c, b} : std::array<std::uint32_t, 3>{a, b, c});
  }
  res_.stats.new_nodes += nv - fixed_count;
  res_.stats.triangles += sm_out.triangles.size();
  ++res_.stats.faces;
  mesh_.surfaces[tag_] = std::move(sm_out);
  res_.target_sizes.push_back({tag_, target_size_fn(sizing_)});
  res_.stats.seconds_output += seconds_since(t0);
  return true;
}

double model_bbox(const geo::Model& model, double given) {
  double bbox = given;
  if (!(bbox > 0)) bbox = model.bounding_box().diagonal();
  if (!(bbox > 0)) bbox = 1;
  return bbox;
}

}  // namespace

Mesh2dResult mesh_surfaces(const geo::Model& model, ModelMesh& mesh, const Mesh2dOptions& opt) {
  Mesh2dResult res;
  const double bbox = model_bbox(model, opt.bbox_diag);
  std::vector<std::uint32_t> local_of;
  progress_begin(opt.progress, "2D", model.surfaces().size());
  std::uint64_t faces_done = 0;
  for (const auto& [tag, s] : model.surfaces()) {
    FaceMesher fm(model, mesh, opt, bbox, res, local_of);
    if (!fm.run(s)) {
      progress_end(opt.progress);
      return res;
    }
    progress_update(opt.progress, ++faces_done);
  }
  progress_end(opt.progress);
  mesh.dim = std::max(mesh.dim, 2);
  return res;
}

Mesh2dResult check_face_budgets(const geo::Model& model, const ModelMesh& coarse, const Mesh2dOptions& base) {
  Mesh2dResult res;
  if (!(base.max_elements > 0)) return res;
  Mesh2dOptions opt = base;
  opt.progress = nullptr;
  ModelMesh mesh = coarse;
  const double bbox = model_bbox(model, opt.bbox_diag);
  std::vector<std::uint32_t> local_of;
  for (const auto& [tag, s] : model.surfaces()) {
    Mesh2dResult face;
    FaceMesher fm(model, mesh, opt, bbox, face, local_of);
    fm.estimate_only();
    if (!fm.run(s) && face.error.kind == Mesh2dErrorKind::LimitExceeded) {
      res.error = face.error;
      return res;
    }
  }
  return res;
}

std::vector<StageTime> stage_times(const Mesh2dStats& s) {
  return {{"2D boundary", s.seconds_boundary},
          {"2D refine", s.seconds_refine},
          {"2D smooth", s.seconds_smooth},
          {"2D optimise", s.seconds_optimize},
          {"2D output", s.seconds_output}};
}

}  // namespace sm
