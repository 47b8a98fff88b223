// 1D meshing (paper section 3.2): adaptive trapezoid integration of |X'|/h piece by piece
// with batched size evaluation, Gmsh's node count and placement, then the self-intersection
// repair of mesh/boundary_recovery on the curves of each plane (parametric or Euclidean).
#include "mesh/mesh1d.h"
#include "mesh/extrude_mesh.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "base/elapsed.h"
#include "base/parallel.h"
#include "base/release_memory.h"
#include "exact/predicates.h"
#include "mesh/boundary_recovery.h"
#include "mesh/compound_curve.h"
#include "mesh/periodic_curve.h"
#include "mesh/transfinite_curve.h"

namespace sm {

std::size_t ModelMesh::num_curve_edges() const {
  std::size_t n = 0;
  for (const auto& [tag, c] : curves) n += c.num_edges();
  return n;
}

std::vector<std::uint32_t> ModelMesh::curve_nodes(int signed_tag) const {
  const auto it = curves.find(std::abs(signed_tag));
  if (it == curves.end()) return {};
  std::vector<std::uint32_t> n = it->second.nodes;
  if (signed_tag < 0) std::reverse(n.begin(), n.end());
  return n;
}

namespace {

// Integrand |X'(t)| / h(t) at a batch of parameters, and |X'(t)| (the smoothing needs it).
void integrand(const geo::Curve& c, const CurveSizeFn& size, std::span<const double> t, std::vector<geo::Jet3>& jets,
               std::vector<double>& h, std::vector<double>& f, std::vector<double>& xp) {
  jets.resize(t.size());
  h.resize(t.size());
  f.resize(t.size());
  xp.resize(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) jets[i] = c.eval(t[i]);
  size(t, jets, h);
  for (std::size_t i = 0; i < t.size(); ++i) {
    xp[i] = norm(jets[i].d1);
    f[i] = xp[i] / h[i];
  }
}

}  // namespace

namespace {

// Gmsh's smoothPrimitive (meshGEdge.cpp): with h = |X'| / f the size at a sample, the
// growth dh/ds along the curve is limited to alpha - 1, by Gauss-Seidel sweeps forward
// and backward until no sample changes.
void smooth_sizes(const std::vector<double>& t, const std::vector<double>& xp, std::vector<double>& f, double alpha) {
  const double slope = alpha - 1;
  for (int sweep = 0; sweep < 2000; ++sweep) {
    std::size_t changed = 0;
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (!(xp[i] > 0) || !(f[i] > 0) || !(f[i - 1] > 0)) continue;
      const double h0 = xp[i - 1] / f[i - 1], h1 = xp[i] / f[i], dt = t[i] - t[i - 1];
      if ((h1 - h0) / dt / xp[i] > slope * 1.01) {
        f[i] = xp[i] / (h0 + dt * slope * xp[i]);
        ++changed;
      }
    }
    for (std::size_t i = t.size() - 1; i > 0; --i) {
      if (!(xp[i - 1] > 0) || !(f[i] > 0) || !(f[i - 1] > 0)) continue;
      const double h0 = xp[i - 1] / f[i - 1], h1 = xp[i] / f[i], dt = t[i] - t[i - 1];
      if ((h0 - h1) / dt / xp[i - 1] > slope * 1.01) {
        f[i - 1] = xp[i - 1] / (h1 + dt * slope * xp[i - 1]);
        ++changed;
      }
    }
    if (changed == 0) break;
  }
}

}  // namespace

CurvePrimitive integrate_curve(const geo::Curve& c, const CurveSizeFn& size, double rel_tolerance, double abs_tolerance,
                               double smooth_ratio) {
  // The curve is smooth inside each polynomial piece: start from a few intervals per piece
  // (so piece boundaries are grid points), then halve, in batches, every interval whose
  // trapezoid disagrees with the sum of its two halves.
  const int pieces = std::max(1, c.pieces());
  const int per_piece = std::max(2, (32 + pieces - 1) / pieces);
  const std::size_t n0 = static_cast<std::size_t>(pieces) * static_cast<std::size_t>(per_piece);
  std::vector<double> t(n0 + 1), f, xp;
  for (std::size_t i = 0; i <= n0; ++i) t[i] = static_cast<double>(i) / static_cast<double>(n0);
  std::vector<geo::Jet3> jets;
  std::vector<double> h;
  CurvePrimitive out;
  integrand(c, size, t, jets, h, f, xp);
  out.evaluations += t.size();
  std::vector<std::uint8_t> active(n0, 1);  // per interval
  std::vector<double> mid_t, mid_f, mid_xp, nt, nf, nxp;
  std::vector<std::uint8_t> nactive;
  constexpr int kMaxPasses = 40;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    mid_t.clear();
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      if (active[i]) mid_t.push_back(0.5 * (t[i] + t[i + 1]));
    if (mid_t.empty()) break;
    integrand(c, size, mid_t, jets, h, mid_f, mid_xp);
    out.evaluations += mid_t.size();
    nt.clear(), nf.clear(), nxp.clear(), nactive.clear();
    std::size_t k = 0;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      nt.push_back(t[i]);
      nf.push_back(f[i]);
      nxp.push_back(xp[i]);
      if (!active[i]) {
        nactive.push_back(0);
        continue;
      }
      const double w = t[i + 1] - t[i], fm = mid_f[k], tm = mid_t[k], xm = mid_xp[k];
      ++k;
      const double t1 = 0.5 * w * (f[i] + f[i + 1]);
      const double t2 = 0.25 * w * (f[i] + 2 * fm + f[i + 1]);
      const bool again = std::abs(t1 - t2) > rel_tolerance * std::abs(t2) + abs_tolerance && 0.5 * w > 1e-13;
      nt.push_back(tm);
      nf.push_back(fm);
      nxp.push_back(xm);
      nactive.push_back(again);
      nactive.push_back(again);
    }
    nt.push_back(t.back());
    nf.push_back(f.back());
    nxp.push_back(xp.back());
    t.swap(nt), f.swap(nf), xp.swap(nxp), active.swap(nactive);
  }
  if (smooth_ratio > 1) smooth_sizes(t, xp, f, std::sqrt(smooth_ratio));
  out.t = std::move(t);
  // Grown pass by pass, t has up to twice its size in capacity: a curve's primitive may be
  // held until every count is checked (mesh1d.cpp's take_parameters).
  out.t.shrink_to_fit();
  out.a.resize(out.t.size());
  out.a[0] = 0;
  for (std::size_t i = 1; i < out.t.size(); ++i)
    out.a[i] = out.a[i - 1] + 0.5 * (out.t[i] - out.t[i - 1]) * (f[i - 1] + f[i]);
  return out;
}

double node_count(const CurvePrimitive& p, int min_segs) {
  const double a = p.total();
  if (!std::isfinite(a)) return a;
  return std::max(static_cast<double>(min_segs) + 1, std::floor(a + 1.99));
}

std::vector<double> place_nodes(const CurvePrimitive& p, int min_segs, int max_nodes) {
  const double count = node_count(p, min_segs);
  // The double -> int conversion below is defined only for counts an int holds.
  if (!(count <= kMaxCurveNodes)) return {};
  int n = static_cast<int>(count);
  if (max_nodes > 0) n = std::min(n, std::max(max_nodes, 2));
  return place_n_nodes(p, n);
}

std::vector<double> place_n_nodes(const CurvePrimitive& p, int n) {
  n = std::max(n, 2);
  const double a = p.total();
  std::vector<double> out(static_cast<std::size_t>(n));
  out.front() = 0;
  out.back() = 1;
  std::size_t j = 0;
  for (int i = 1; i + 1 < n; ++i) {
    if (!(a > 0)) {
      out[i] = static_cast<double>(i) / (n - 1);
      continue;
    }
    const double target = a * i / (n - 1);
    while (j + 2 < p.a.size() && p.a[j + 1] < target) ++j;
    const double da = p.a[j + 1] - p.a[j];
    const double s = da > 0 ? std::clamp((target - p.a[j]) / da, 0.0, 1.0) : 0.5;
    out[i] = p.t[j] + s * (p.t[j + 1] - p.t[j]);
  }
  return out;
}

int min_segments(const geo::Curve& c, const Mesh1dOptions& opt) {
  int np = 1;
  switch (c.kind()) {
    case geo::CurveKind::Line: np = 1; break;
    case geo::CurveKind::Circle:
    case geo::CurveKind::Ellipse: {
      // The arc's share of a full turn (an ellipse's in its eccentric angle), as Gmsh
      // 4.8.4 counts Mesh.MinimumCircleNodes for both: a quarter ellipse gets a quarter.
      const double angle =
          c.kind() == geo::CurveKind::Circle ? std::abs(c.circle()->angle) : std::abs(c.ellipse()->sweep);
      const double n = opt.min_circle_nodes;
      np = angle > 6.28 ? static_cast<int>(n) : static_cast<int>(0.99 + (n - 1) * angle / (2 * std::numbers::pi));
      break;
    }
    default: np = opt.min_curve_nodes - 1; break;
  }
  return std::max(np, 1);
}

namespace {

struct CurveJob {
  const geo::ModelCurve* mc = nullptr;
  const geo::Curve* shape = nullptr;
};

MeshError make_error(MeshErrorKind kind, int a, int b, MeshProblem problem = MeshProblem::None,
                     std::array<long long, 5> numbers = {}) {
  MeshError e;
  e.kind = kind;
  e.problem = problem;
  e.add_entity(1, a);
  e.add_entity(1, b);
  e.numbers = numbers;
  return e;
}

// A failure of the crossing repair other than a crossing (boundary_recovery.h) as the mesh
// kernel's problem, with its values.
void repair_problem(const BoundaryError& b, MeshError& e) {
  e.numbers = {b.curve_a, b.point_a, static_cast<long long>(b.count)};
  e.value = b.parameter;
  e.reason = b.reason;
  switch (b.fault) {
    case BoundaryFault::RoundsExhausted:
      e.numbers[0] = static_cast<long long>(b.count);
      e.problem = MeshProblem::RepairRoundsExhausted;
      return;
    case BoundaryFault::CurveTooFewPoints: e.problem = MeshProblem::RepairCurveTooFewPoints; return;
    case BoundaryFault::PointOutOfRange: e.problem = MeshProblem::RepairPointOutOfRange; return;
    case BoundaryFault::NoPointAtParameter: e.problem = MeshProblem::RepairNoPointAtParameter; return;
    case BoundaryFault::TriangulationFailed: e.problem = MeshProblem::RepairTriangulationFailed; return;
    case BoundaryFault::EdgeRecoveryFailed: e.problem = MeshProblem::RepairEdgeRecoveryFailed; return;
    case BoundaryFault::None: return;
  }
}

// The curves drawn in one plane: a surface geometry's (u,v) plane (key = its tag) or the
// Euclidean plane z = const (key 0). Crossing edges are searched there.
struct PlaneGroup {
  int geometry = 0;
  double z = 0;
  std::vector<int> curves;  // tags
};

bool all_collinear(const std::vector<Vec2>& p) {
  if (p.size() < 3) return true;
  std::size_t j = 1;
  while (j < p.size() && p[j] == p[0]) ++j;
  if (j == p.size()) return true;
  for (std::size_t k = j + 1; k < p.size(); ++k)
    if (orient2d(p[0], p[j], p[k]) != Sign::Zero) return false;
  return true;
}

MeshError repair_group(const geo::Model& model, const PlaneGroup& g, ModelMesh& mesh, const Mesh1dOptions& opt,
                       Mesh1dStats& st) {
  const geo::SurfaceGeometry* geom = g.geometry ? model.geometry(g.geometry) : nullptr;
  auto plane_of = [&](const MeshNode& n) { return geom ? n.uv : Vec2{n.xyz.x, n.xyz.y}; };
  BoundaryProblem prob;
  std::vector<std::uint32_t> node_to_pt(mesh.nodes.size(), kNoEdge);
  std::vector<std::uint32_t> pt_to_node;
  for (int tag : g.curves) {
    const CurveMesh& cm = mesh.curves.at(tag);
    BoundaryCurve bc;
    bc.id = static_cast<std::uint32_t>(tag);
    bc.t = cm.t;
    for (std::uint32_t n : cm.nodes) {
      if (node_to_pt[n] == kNoEdge) {
        node_to_pt[n] = static_cast<std::uint32_t>(prob.points.size());
        prob.points.push_back(plane_of(mesh.nodes[n]));
        pt_to_node.push_back(n);
      }
      bc.pts.push_back(node_to_pt[n]);
    }
    prob.curves.push_back(std::move(bc));
  }
  if (all_collinear(prob.points)) return {};
  const std::size_t original = prob.points.size();
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  for (Vec2 p : prob.points)
    lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y), hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
  BoundaryOptions bo;
  bo.tolerance = model.options().tolerance * std::hypot(hi_x - lo_x, hi_y - lo_y);
  bo.max_rounds = opt.max_repair_rounds;
  auto split = [&](std::uint32_t c, double t) -> Vec2 {
    const geo::Curve& shape = *model.curve(g.curves[c])->shape;
    if (geom) return shape.eval_uv(t).p;
    const Vec3 p = shape.point(t);
    return {p.x, p.y};
  };
  BoundaryResult br = recover_boundary(prob, split, bo);
  st.repair_rounds += br.rounds;
  st.repair_splits += br.splits;
  if (!br.ok()) {
    MeshErrorKind kind = MeshErrorKind::Invalid;
    if (br.error.kind == BoundaryErrorKind::Intersection) kind = MeshErrorKind::Intersection;
    if (br.error.kind == BoundaryErrorKind::DuplicatePoint) kind = MeshErrorKind::DuplicatePoint;
    if (br.error.kind == BoundaryErrorKind::NoProgress) kind = MeshErrorKind::NoProgress;
    MeshError e = make_error(kind, static_cast<int>(br.error.curve_a), static_cast<int>(br.error.curve_b));
    const Vec2 w = br.error.where;
    e.xyz = geom ? geom->point(w) : Vec3{w.x, w.y, g.z};
    if (geom && geom->polar()) {
      e.has_lonlat = true;
      e.where = geom->polar()->to_lonlat(e.xyz);
    } else if (geom && geom->lonlat()) {
      e.has_lonlat = true;
      e.where = {w.x * geo::kRadToDeg, w.y * geo::kRadToDeg};
    }
    // A crossing or a duplicate node is told by its kind, curves and place (the interpreter
    // words it); any other failure keeps the recovery's own words.
    if (kind != MeshErrorKind::Intersection && kind != MeshErrorKind::DuplicatePoint) repair_problem(br.error, e);
    return e;
  }
  if (br.splits == 0) return {};
  // New points: one node each, on the curve that received it.
  pt_to_node.resize(prob.points.size(), kNoEdge);
  for (std::size_t ci = 0; ci < prob.curves.size(); ++ci) {
    const BoundaryCurve& bc = prob.curves[ci];
    const geo::Curve& shape = *model.curve(g.curves[ci])->shape;
    CurveMesh& cm = mesh.curves.at(g.curves[ci]);
    if (bc.pts.size() == cm.nodes.size()) continue;
    cm.nodes.clear();
    cm.t = bc.t;
    for (std::size_t k = 0; k < bc.pts.size(); ++k) {
      const std::uint32_t p = bc.pts[k];
      if (p >= original && pt_to_node[p] == kNoEdge) {
        const double t = bc.t[k];
        pt_to_node[p] = geom ? mesh.add_node(shape.point(t), shape.eval_uv(t).p) : mesh.add_node(shape.point(t));
      }
      cm.nodes.push_back(pt_to_node[p]);
    }
  }
  return {};
}

// Gmsh: the vertex of a closed curve that no other curve touches is not tied to its
// control point: its node moves to the curve's start (a periodic B-spline does not pass
// through its first control point). Per vertex tag, the curves beginning or ending there.
std::map<int, int> curves_at_vertices(const geo::Model& model) {
  std::map<int, int> curves_at;
  for (const auto& [tag, mc] : model.curves()) {
    ++curves_at[mc.begin];
    if (mc.end != mc.begin) ++curves_at[mc.end];
  }
  return curves_at;
}

// Whether the node of closed curve mc's vertex moves to the curve's start.
bool vertex_moves(const std::map<int, int>& curves_at, const geo::ModelCurve& mc) {
  return mc.begin == mc.end && curves_at.at(mc.begin) == 1;
}

// A progress stage, ended on every return, errors included.
struct StageEnd {
  Progress* p;
  bool open = false;
  void begin(std::string_view name, std::uint64_t total) {
    end();
    progress_begin(p, name, total);
    open = true;
  }
  void end() {
    if (open) progress_end(p);
    open = false;
  }
  ~StageEnd() { end(); }
};

// One plan per curve in tag order. The curves are independent until their nodes are
// numbered: the integral, the placement and the nodes' coordinates are computed on
// opt.threads threads, each curve into its own plan; errors and exceptions are kept in
// the plan and taken up in tag order afterwards, so that the first failing curve is the
// one a serial loop would report and the nodes are numbered as one thread numbers them.
struct CurvePlan {
  int tag = 0;
  const geo::ModelCurve* mc = nullptr;
  bool moves_vertex = false;
  std::optional<double> lc0, lc1;
  double stretch = 1;
  // The size integral's samples, freed once the node parameters are taken from them
  // (take_parameters); its total and evaluations are kept apart for the budget check.
  CurvePrimitive prim;
  double total = 0;
  std::uint64_t evaluations = 0;
  int min_segs = 1;
  double nodes = 0;
  bool in_compound = false;  // a `Compound Curve` member: plan_compounds reads its primitive
  bool parameters_taken = false;  // ts (and coarse_ts) hold the primitive's placement
  std::vector<double> coarse_ts;  // the coarse mesh's parameters, when taken early
  MeshError error;            // no shape, no end point
  std::exception_ptr thrown;  // from the background field
  std::vector<double> ts;     // the nodes' parameters, first 0 and last 1
  std::vector<Vec3> xyz;      // interior nodes
  std::vector<Vec2> uv;       // interior nodes, on a surface's curve
  const TransfiniteCurveSpec* transfinite = nullptr;
  bool odd = false;  // bounds a recombined surface: an odd node count
  bool collapsed = false;  // zero length between coincident points: one node, no edge
  // Boundary-layer points from the begin / end vertex (distances along the line), when
  // the curve leaves a layer's end point (Mesh1dOptions::boundary_layers).
  std::vector<double> layer_begin, layer_end;
  /// In a `Compound Curve`: its nodes' parameters, shared out of the chain's (plan_compounds).
  std::optional<std::vector<double>> compound_ts;
};

// The layer points of curve cp at its ends (Gmsh 4.8.4, meshGEdge.cpp: a curve not in a
// field's CurvesList leaving one of its PointsList points gets points at the layer
// heights while they are within Thickness and 0.4 of the curve's chord); the curve must
// be straight there. Sets cp.error on a curve that cannot take them.
void plan_layer_points(const geo::Model& model, const Mesh1dOptions& opt, CurvePlan& cp) {
  if (!opt.boundary_layers || cp.transfinite) return;
  const geo::ModelCurve& mc = *cp.mc;
  const geo::ModelVertex* vb = model.vertex(mc.begin);
  const geo::ModelVertex* ve = model.vertex(mc.end);
  if (!vb || !ve || !mc.shape || mc.begin == mc.end) return;
  for (const field::BoundaryLayerParams& p : *opt.boundary_layers) {
    if (p.has_curve(cp.tag)) return;  // a layer curve itself is meshed as it is
  }
  const double chord = norm(ve->xyz - vb->xyz);
  for (const field::BoundaryLayerParams& p : *opt.boundary_layers) {
    for (int end = 0; end < 2; ++end) {
      const int vtag = end == 0 ? mc.begin : mc.end;
      if (!p.is_end_point(vtag)) continue;
      if (mc.shape->kind() != geo::CurveKind::Line) {
        cp.error = make_error(MeshErrorKind::Invalid, cp.tag, cp.tag, MeshProblem::LayerEndCurved, {vtag});
        return;
      }
      std::vector<double>& d = end == 0 ? cp.layer_begin : cp.layer_end;
      if (!d.empty()) {
        cp.error = make_error(MeshErrorKind::Invalid, cp.tag, cp.tag, MeshProblem::LayersTouch, {vtag});
        return;
      }
      d = field::layer_distances(p, p.size_at_point(vtag), std::min(p.thickness, 0.4 * chord));
      // The beta law has no limit: its points stay inside the curve all the same.
      while (!d.empty() && d.back() >= 0.4 * chord) d.pop_back();
    }
  }
  // The two ends' points must not meet.
  if (!cp.layer_begin.empty() && !cp.layer_end.empty() && cp.layer_begin.back() + cp.layer_end.back() >= chord)
    cp.layer_end.clear();
}

// The primitive a(t) at t, interpolated between its samples.
double primitive_at(const CurvePrimitive& p, double t) {
  if (p.t.empty()) return 0;
  const auto it = std::upper_bound(p.t.begin(), p.t.end(), t);
  if (it == p.t.begin()) return p.a.front();
  if (it == p.t.end()) return p.a.back();
  const std::size_t j = static_cast<std::size_t>(it - p.t.begin());
  const double dt = p.t[j] - p.t[j - 1];
  const double s = dt > 0 ? (t - p.t[j - 1]) / dt : 0.0;
  return p.a[j - 1] + s * (p.a[j] - p.a[j - 1]);
}

// The parameter where the primitive reaches `target` (a between the samples).
double primitive_inverse(const CurvePrimitive& p, double target) {
  const auto it = std::lower_bound(p.a.begin(), p.a.end(), target);
  if (it == p.a.begin()) return p.t.front();
  if (it == p.a.end()) return p.t.back();
  const std::size_t j = static_cast<std::size_t>(it - p.a.begin());
  const double da = p.a[j] - p.a[j - 1];
  const double s = da > 0 ? (target - p.a[j - 1]) / da : 0.5;
  return p.t[j - 1] + s * (p.t[j] - p.t[j - 1]);
}

// The node parameters of a curve with layer points: those points at its ends, the part
// between them meshed as the whole curve is (Gmsh's count N = int(a + 1.99) of the
// part's integral, at equal increments of it).
std::vector<double> layered_parameters(const CurvePlan& cp, double length) {
  std::vector<double> ts{0.0};
  for (double d : cp.layer_begin) ts.push_back(d / length);
  const double tb = cp.layer_begin.empty() ? 0.0 : cp.layer_begin.back() / length;
  const double te = cp.layer_end.empty() ? 1.0 : 1.0 - cp.layer_end.back() / length;
  const double ab = primitive_at(cp.prim, tb), ae = primitive_at(cp.prim, te);
  const double part = std::max(0.0, ae - ab);
  const int n = static_cast<int>(std::min(std::floor(part + 1.99), kMaxCurveNodes - 1));
  for (int i = 1; i + 1 < n; ++i) ts.push_back(primitive_inverse(cp.prim, ab + part * i / (n - 1)));
  if (!cp.layer_end.empty()) ts.push_back(te);
  for (std::size_t i = cp.layer_end.size(); i-- > 1;) ts.push_back(1.0 - cp.layer_end[i - 1] / length);
  ts.push_back(1.0);
  // Strictly increasing (the curve mesh's contract): a part too short for its own nodes
  // gives none, and the layer points stay.
  std::vector<double> out;
  for (double t : ts)
    if (out.empty() || t > out.back()) out.push_back(t);
  if (out.back() != 1.0) out.back() = 1.0;
  return out;
}

// Curves bounding a recombined surface (Gmsh's forced odd count: meshGEdge.cpp), sorted.
std::vector<int> odd_count_curves(const geo::Model& model, const Mesh1dOptions& opt) {
  std::vector<int> odd_curves;
  if (const MeshConstraints* mc = opt.constraints; mc && mc->algorithm == RecombineAlgorithm::Matching) {
    for (const auto& [stag, s] : model.surfaces()) {
      if (!mc->recombines(stag)) continue;
      for (int l : s.loops)
        if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
          for (int c : loop->curves) odd_curves.push_back(std::abs(c));
    }
    std::sort(odd_curves.begin(), odd_curves.end());
  }
  return odd_curves;
}

// The plans of the model's curves in tag order, transfinite and forced odd ones marked.
std::vector<CurvePlan> make_plans(const geo::Model& model, const Mesh1dOptions& opt,
                                  const std::map<int, int>& curves_at, const std::vector<int>& collapsed) {
  std::vector<CurvePlan> plans;
  plans.reserve(model.curves().size());
  const std::vector<int> odd_curves = odd_count_curves(model, opt);
  std::vector<int> compound_members;
  if (opt.constraints)
    for (const std::vector<int>& group : opt.constraints->compound_curves)
      for (int c : group) compound_members.push_back(std::abs(c));
  std::sort(compound_members.begin(), compound_members.end());
  for (const auto& [tag, mc] : model.curves()) {
    CurvePlan& cp = plans.emplace_back();
    cp.tag = tag;
    cp.mc = &mc;
    cp.moves_vertex = vertex_moves(curves_at, mc);
    if (opt.constraints)
      if (const auto it = opt.constraints->curves.find(tag); it != opt.constraints->curves.end())
        cp.transfinite = &it->second;
    cp.odd = !cp.transfinite && std::binary_search(odd_curves.begin(), odd_curves.end(), tag);
    cp.collapsed = std::binary_search(collapsed.begin(), collapsed.end(), tag);
    cp.in_compound = std::binary_search(compound_members.begin(), compound_members.end(), tag);
  }
  return plans;
}

// Each curve's size h(t) along it: the policy with the background field, the end
// points' sizes and the curvature, times the Bezier stretch. The scratch for the field's
// points is the function's own (one per curve and pass, so per thread).
auto curve_size(const Mesh1dOptions& opt, double bbox, const CurvePlan& cp) {
  return [&opt, bbox, &cp, on = field::EntityRef{1, cp.tag}, pts = std::vector<Vec3>(), bg = std::vector<double>()](
             std::span<const double> t, std::span<const geo::Jet3> jets, std::span<double> h) mutable {
    if (opt.background) {
      pts.resize(t.size());
      bg.resize(t.size());
      for (std::size_t i = 0; i < t.size(); ++i) pts[i] = jets[i].p;
      opt.background->eval_on(on, pts, bg);
    }
    field::SizeQuery q;
    q.bbox_diag = bbox;
    q.entity_dim = 1;
    q.end_lc0 = cp.lc0;
    q.end_lc1 = cp.lc1;
    const bool curvature = opt.size.from_curvature > 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      q.t = t[i];
      if (opt.background) q.background = bg[i];
      if (curvature) {
        const double d = norm(jets[i].d1);
        q.curvature = d > 0 ? norm(cross(jets[i].d1, jets[i].d2)) / (d * d * d) : 0.0;
      }
      h[i] = cp.stretch * field::final_size(opt.size, q).size;
    }
  };
}

// Every curve's primitive was held until the budget check, and with it the 1D peak (16
// bytes a sample, about 8 samples a node on the full GSHHG at 3 km; docs/kernel.md,
// "Memory"). A curve whose count is known needs only the parameters place_plan and
// coarse_mesh take from it: they are taken now and the primitive freed, where they are
// no larger than it (so a count beyond the budget still costs no more than its samples).
// A layered curve or a compound's member reads its primitive later: kept.
void take_parameters(const Mesh1dOptions& opt, CurvePlan& cp) {
  const bool layered = !cp.layer_begin.empty() || !cp.layer_end.empty();
  if (layered || cp.in_compound || !(cp.nodes <= static_cast<double>(cp.prim.t.size()))) return;
  const int n = static_cast<int>(cp.nodes);
  if (opt.max_elements > 0 && opt.coarse_check) cp.coarse_ts = place_n_nodes(cp.prim, std::min(n, kCoarseCurveNodes));
  cp.ts = place_n_nodes(cp.prim, n);
  cp.parameters_taken = true;
  cp.prim = {};
}

// Curve cp's size integral, hence its node count (its error or exception kept in it).
void integrate_plan(const geo::Model& model, const Mesh1dOptions& opt, double bbox, CurvePlan& cp) {
  const int tag = cp.tag;
  const geo::ModelCurve& mc = *cp.mc;
  if (!mc.shape) {
    cp.error = make_error(MeshErrorKind::Invalid, tag, tag, MeshProblem::CurveNoGeometry);
    return;
  }
  const geo::Curve& shape = *mc.shape;
  const geo::ModelVertex* vb = model.vertex(mc.begin);
  const geo::ModelVertex* ve = model.vertex(mc.end);
  if (!vb || !ve) {
    cp.error = make_error(MeshErrorKind::Invalid, tag, tag, MeshProblem::CurveNoEndPoint);
    return;
  }
  if (vb->lc < geo::kMaxLc) cp.lc0 = vb->lc;
  if (ve->lc < geo::kMaxLc) cp.lc1 = ve->lc;
  if (cp.collapsed) {
    cp.nodes = 1;
    return;
  }
  // Gmsh 4.8.4 integrates a Bezier curve of degree d with |X'| / d (measured: a
  // 3-point Bezier of length 3 at lc 0.1 gets 16 segments, a 6-point one 7), so its
  // node count is d times smaller than the sizes ask; we follow it for compatibility.
  if (cp.transfinite) {  // the count is the script's, the law places the nodes
    cp.nodes = std::max(cp.transfinite->nodes, 2);
    return;
  }
  cp.stretch = shape.kind() == geo::CurveKind::Bezier
                   ? static_cast<double>(std::max<std::size_t>(1, shape.control_xyz().size() - 1))
                   : 1.0;
  try {
    cp.prim = integrate_curve(shape, curve_size(opt, bbox, cp), opt.rel_tolerance, opt.abs_tolerance, opt.smooth_ratio);
  } catch (...) {
    cp.thrown = std::current_exception();
    return;
  }
  cp.min_segs = min_segments(shape, opt);
  cp.total = cp.prim.total();
  cp.evaluations = cp.prim.evaluations;
  cp.nodes = node_count(cp.prim, cp.min_segs);
  plan_layer_points(model, opt, cp);
  if (!cp.layer_begin.empty() || !cp.layer_end.empty())
    cp.nodes += static_cast<double>(cp.layer_begin.size() + cp.layer_end.size());
  if (cp.odd && cp.nodes <= kMaxCurveNodes - 1 && std::fmod(cp.nodes, 2.0) == 0) cp.nodes += 1;
  take_parameters(opt, cp);
}

// The node counts in tag order (errors and exceptions of the integration taken up there,
// so that the first failing curve is the one a serial loop would report) against
// kMaxCurveNodes and Mesh.MaxElements, per curve and in all: false with res.error set.
// The total into total_nodes.
bool check_node_budget(std::vector<CurvePlan>& plans, const Mesh1dOptions& opt, Mesh1dResult& res,
                       double& total_nodes) {
  total_nodes = 0;
  std::size_t largest = 0;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    CurvePlan& cp = plans[i];
    const int tag = cp.tag;
    if (cp.thrown) std::rethrow_exception(cp.thrown);
    if (!cp.error.ok()) {
      res.error = std::move(cp.error);
      return false;
    }
    res.stats.size_evaluations += cp.evaluations;
    if (!std::isfinite(cp.total)) {
      res.error = make_error(MeshErrorKind::Invalid, tag, tag, MeshProblem::CurveSizeNotFinite);
      return false;
    }
    const double limit = opt.max_elements > 0 ? std::min(opt.max_elements, kMaxCurveNodes) : kMaxCurveNodes;
    if (!(cp.nodes <= limit)) {
      res.error = make_error(MeshErrorKind::LimitExceeded, tag, tag);
      res.error.count = cp.nodes;
      res.error.limit = limit;
      return false;
    }
    total_nodes += cp.nodes;
    if (i == 0 || cp.nodes > plans[largest].nodes) largest = i;
  }
  if (opt.max_elements > 0 && total_nodes > opt.max_elements) {
    const int tag = plans[largest].tag;
    res.error = make_error(MeshErrorKind::LimitExceeded, tag, tag);
    res.error.count = total_nodes;
    res.error.limit = opt.max_elements;
    res.error.all_curves = true;
    return false;
  }
  return true;
}

// The most nodes placed while the coarse check runs (mesh_curves).
constexpr double kOverlapNodes = 2e6;

// The coarse 1D mesh for Mesh1dOptions::coarse_check: kCoarseCurveNodes nodes per curve
// at equal increments of its size integral (a transfinite curve its own), with the 1D
// sizes at the nodes (CurveMesh::h), no repair. The curves' parameters, then their nodes'
// places and sizes (the background field's evaluations), are computed on `threads`
// threads, each curve into its own arrays; the nodes are numbered in between, in plan
// order, as one thread numbers them.
ModelMesh coarse_mesh(const std::vector<CurvePlan>& plans, const Mesh1dOptions& opt, double bbox,
                      const ModelMesh& mesh, int threads) {
  ModelMesh coarse;
  coarse.dim = 1;
  coarse.nodes = mesh.nodes;
  coarse.vertex_node = mesh.vertex_node;
  std::vector<std::vector<double>> ts(plans.size());
  parallel_for_chunks(threads, plans.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const CurvePlan& cp = plans[i];
      if (cp.collapsed) continue;
      ts[i] = cp.transfinite       ? transfinite_parameters(*cp.mc->shape, *cp.transfinite)
              : cp.parameters_taken ? cp.coarse_ts
                                    : place_n_nodes(cp.prim, static_cast<int>(std::min<double>(cp.nodes, kCoarseCurveNodes)));
    }
  });
  std::vector<CurveMesh*> placed(plans.size(), nullptr);
  for (std::size_t i = 0; i < plans.size(); ++i) {
    const CurvePlan& cp = plans[i];
    CurveMesh cm;
    cm.tag = cp.tag;
    if (cp.collapsed) {
      cm.t = {0.0};
      cm.nodes = {coarse.vertex_node.at(cp.mc->begin)};
      cm.h = {cp.lc0.value_or(bbox)};
      coarse.curves.emplace(cp.tag, std::move(cm));
      continue;
    }
    cm.t = std::move(ts[i]);
    cm.nodes.push_back(coarse.vertex_node.at(cp.mc->begin));
    for (std::size_t k = 1; k + 1 < cm.t.size(); ++k) cm.nodes.push_back(static_cast<std::uint32_t>(coarse.nodes.size() + k - 1));
    cm.nodes.push_back(coarse.vertex_node.at(cp.mc->end));
    coarse.nodes.resize(coarse.nodes.size() + (cm.t.size() >= 2 ? cm.t.size() - 2 : 0));
    placed[i] = &coarse.curves.emplace(cp.tag, std::move(cm)).first->second;
  }
  parallel_for_chunks(threads, plans.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!placed[i]) continue;
      const CurvePlan& cp = plans[i];
      CurveMesh& cm = *placed[i];
      const geo::Curve& shape = *cp.mc->shape;
      const bool uv = shape.on_surface();
      for (std::size_t k = 1; k + 1 < cm.t.size(); ++k) {
        MeshNode& n = coarse.nodes[cm.nodes[k]];
        n.xyz = shape.point(cm.t[k]);
        if (uv) n.uv = shape.eval_uv(cm.t[k]).p, n.has_uv = true;
      }
      std::vector<geo::Jet3> jets(cm.t.size());
      for (std::size_t k = 0; k < cm.t.size(); ++k) jets[k] = shape.eval(cm.t[k]);
      cm.h.resize(cm.t.size());
      curve_size(opt, bbox, cp)(cm.t, jets, cm.h);
      for (double& h : cm.h) h /= cp.stretch;
    }
  });
  return coarse;
}

// The nodes of curve cp: their parameters and coordinates into cp.ts, cp.xyz, cp.uv.
void place_plan(const geo::Model& model, const Mesh1dOptions& opt, double bbox, CurvePlan& cp) {
  if (cp.collapsed) {
    cp.ts = {0.0};
    return;
  }
  const geo::ModelCurve& mc = *cp.mc;
  if (mc.discrete && !mc.has_geometry) {   // a merged mesh's curve: its nodes, at its polyline's corners
    const std::size_t n = mc.inner.size() + 2;
    cp.ts.resize(n);
    for (std::size_t i = 0; i < n; ++i) cp.ts[i] = static_cast<double>(i) / static_cast<double>(n - 1);
    cp.ts.back() = 1.0;
    cp.xyz = mc.inner;
    cp.uv.clear();
    return;
  }
  const geo::Curve& shape = *mc.shape;
  const geo::ModelVertex* vb = model.vertex(mc.begin);
  const double stretch = cp.stretch;
  const int min_segs = cp.min_segs;
  auto size = curve_size(opt, bbox, cp);
  const bool layered = !cp.layer_begin.empty() || !cp.layer_end.empty();
  std::vector<double> ts = cp.compound_ts  ? std::move(*cp.compound_ts)
                           : cp.transfinite ? transfinite_parameters(shape, *cp.transfinite)
                           : layered        ? layered_parameters(cp, norm(model.vertex(mc.end)->xyz - vb->xyz))
                           : cp.parameters_taken ? std::move(cp.ts)
                                            : place_n_nodes(cp.prim, static_cast<int>(cp.nodes));
  cp.prim = {};  // not needed any more: its samples are the largest part of a plan
  cp.coarse_ts = {};
  // Gmsh's filterPoints: an interior node closer than 0.3 h to the previous node kept
  // (noisy curves, tight turns) is dropped, unless that leaves fewer than the minimum.
  // Sizes come one at a time (each depends on the node kept before), so first a batch
  // screen with every node kept decides whether the curve needs it at all.
  std::vector<Vec3> x;  // the nodes' positions while ts is unfiltered
  // No filter on a transfinite curve (its count is the script's) nor on a forced odd
  // count (dropping a node would make it even again).
  if (ts.size() > 2 && !cp.transfinite && !cp.odd && !layered && !cp.compound_ts) {
    const std::size_t n = ts.size();
    x.resize(n);
    x[0] = cp.moves_vertex ? shape.point(0) : vb->xyz;
    for (std::size_t i = 1; i + 1 < n; ++i) x[i] = shape.point(ts[i]);
    std::vector<double> tm(n - 2), hm(n - 2);
    std::vector<geo::Jet3> jm(n - 2);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      tm[i - 1] = i == 1 ? ts[1] : 0.5 * (ts[i] + ts[i - 1]);
      jm[i - 1] = shape.eval(tm[i - 1]);
    }
    size(tm, jm, hm);
    bool close = false;
    for (std::size_t i = 1; i + 1 < n && !close; ++i) close = norm(x[i] - x[i - 1]) < 0.5 * hm[i - 1] / stretch;
    if (close) {
      std::vector<std::uint8_t> drop(n, 0);
      std::size_t dropped = 0, prev = 0;
      for (std::size_t i = 1; i + 1 < n; ++i) {
        // While the node before was kept, the midpoint is the screen's (the same t, so
        // the same size): only a node after a dropped one needs its own evaluation.
        double h = hm[i - 1];
        if (prev + 1 != i) {
          const double t = 0.5 * (ts[i] + ts[prev]);
          const geo::Jet3 j = shape.eval(t);
          size(std::span<const double>(&t, 1), std::span<const geo::Jet3>(&j, 1), std::span<double>(&h, 1));
        }
        if (norm(x[i] - x[prev]) < 0.3 * h / stretch) {
          drop[i] = 1;
          ++dropped;
        } else {
          prev = i;
        }
      }
      if (dropped > 0 && static_cast<int>(n - 2 - dropped) >= min_segs + 1 - 2) {
        std::vector<double> kept;
        for (std::size_t i = 0; i < n; ++i)
          if (!drop[i]) kept.push_back(ts[i]);
        ts.swap(kept);
        x.clear();
      }
    }
  }
  const bool on_surface = shape.on_surface();
  const std::size_t interior = ts.size() >= 2 ? ts.size() - 2 : 0;
  cp.xyz.resize(interior);
  if (on_surface) cp.uv.resize(interior);
  for (std::size_t i = 0; i < interior; ++i) {
    cp.xyz[i] = x.empty() ? shape.point(ts[i + 1]) : x[i + 1];
    if (on_surface) cp.uv[i] = shape.eval_uv(ts[i + 1]).p;
  }
  cp.ts = std::move(ts);
}

// `Compound Curve{...}` (compound_curve.h): the chain's nodes at equal increments of the
// sum of its curves' integrals, each curve's share turned into its own parameters. A
// group that is not one chain, or holds a transfinite, collapsed, layered or odd-count
// curve (those counts are the script's or the recombination's), is meshed curve by curve.
void plan_compounds(const geo::Model& model, const Mesh1dOptions& opt, std::vector<CurvePlan>& plans) {
  if (!opt.constraints) return;
  for (const std::vector<int>& group : opt.constraints->compound_curves) {
    const std::vector<CompoundLink> chain = chain_compound(model, group);
    if (chain.empty()) continue;
    std::vector<CurvePlan*> members;
    std::vector<double> totals;
    for (const CompoundLink& l : chain) {
      const auto it = std::lower_bound(plans.begin(), plans.end(), l.curve,
                                       [](const CurvePlan& p, int tag) { return p.tag < tag; });
      if (it == plans.end() || it->tag != l.curve) break;
      CurvePlan& cp = *it;
      if (cp.transfinite || cp.collapsed || cp.odd || cp.compound_ts || !cp.error.ok() || cp.thrown ||
          !cp.layer_begin.empty() || !cp.layer_end.empty() || cp.prim.a.empty())
        break;
      members.push_back(&cp);
      totals.push_back(cp.prim.total());
    }
    if (members.size() != chain.size()) continue;
    // Gmsh meshes the compound as a discrete curve, which takes at least 2 segments, 3 when
    // it is closed (Geo/discreteEdge.h's minimumMeshSegments): a one-curve compound too.
    const CompoundLink& first = chain.front();
    const CompoundLink& last = chain.back();
    const int start = first.reversed ? members.front()->mc->end : members.front()->mc->begin;
    const int finish = last.reversed ? members.back()->mc->begin : members.back()->mc->end;
    const std::vector<std::vector<double>> shares = compound_node_positions(totals, start == finish ? 3 : 2);
    for (std::size_t i = 0; i < members.size(); ++i) {
      CurvePlan& cp = *members[i];
      std::vector<double> ts{0.0};
      for (double pos : shares[i]) ts.push_back(primitive_inverse(cp.prim, chain[i].reversed ? totals[i] - pos : pos));
      ts.push_back(1.0);
      std::sort(ts.begin(), ts.end());
      // Strictly increasing, as a curve mesh's parameters must be.
      ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
      cp.nodes = static_cast<double>(ts.size());
      cp.compound_ts = std::move(ts);
    }
  }
}

// Plan cp's nodes numbered into `mesh` as its curve's mesh.
void number_plan(const geo::Model& model, CurvePlan& cp, ModelMesh& mesh) {
  // A curve Extrude made with Layers: its nodes are the layers' (a top copy its source's,
  // numbered before it), whatever the sizes said (extrude_mesh.h).
  if (!cp.collapsed && extruded_curve_nodes(model, mesh, cp.tag, cp.ts, cp.xyz)) cp.uv.clear();
  const geo::ModelCurve& mc = *cp.mc;
  CurveMesh cm;
  cm.tag = cp.tag;
  cm.nodes.reserve(cp.ts.size());
  cm.nodes.push_back(mesh.vertex_node.at(mc.begin));
  if (cp.collapsed) {  // its end's node is its start's
    cm.t = std::move(cp.ts);
    mesh.curves.emplace(cp.tag, std::move(cm));
    return;
  }
  for (std::size_t i = 0; i < cp.xyz.size(); ++i)
    cm.nodes.push_back(cp.uv.empty() ? mesh.add_node(cp.xyz[i]) : mesh.add_node(cp.xyz[i], cp.uv[i]));
  cm.nodes.push_back(mesh.vertex_node.at(mc.end));
  cm.t = std::move(cp.ts);
  cp.xyz = {}, cp.uv = {};
  mesh.curves.emplace(cp.tag, std::move(cm));
}

// A `Periodic Curve` target's nodes copied from its source's mesh (periodic_curve.h).
MeshError copy_periodic_plan(const geo::Model& model, const PeriodicCurveSpec& spec, CurvePlan& cp,
                             ModelMesh& mesh) {
  MeshError why;
  if (!periodic_curve_nodes(model, mesh, cp.tag, spec, cp.ts, cp.xyz, &why)) return why;
  cp.uv.clear();
  if (cp.mc->shape->on_surface())
    for (std::size_t i = 1; i + 1 < cp.ts.size(); ++i) cp.uv.push_back(cp.mc->shape->eval_uv(cp.ts[i]).p);
  number_plan(model, cp, mesh);
  return {};
}

// The placed nodes numbered into `mesh`, curve by curve in tag order (exceptions of the
// placement rethrown there), as one thread numbers them; then the periodic targets,
// each once its source has its mesh: a round numbers at least one of those left, or the
// rest copy one another in a cycle.
MeshError number_nodes(const geo::Model& model, const Mesh1dOptions& opt, std::vector<CurvePlan>& plans,
                       ModelMesh& mesh) {
  const std::map<int, PeriodicCurveSpec> none;
  const std::map<int, PeriodicCurveSpec>& periodic = opt.constraints ? opt.constraints->periodic_curves : none;
  std::vector<CurvePlan*> copies;
  for (CurvePlan& cp : plans) {
    if (cp.thrown) std::rethrow_exception(cp.thrown);
    if (!cp.collapsed && periodic.count(cp.tag)) copies.push_back(&cp);
    else number_plan(model, cp, mesh);
  }
  while (!copies.empty()) {
    std::vector<CurvePlan*> waiting;
    for (CurvePlan* cp : copies) {
      const PeriodicCurveSpec& spec = periodic.at(cp->tag);
      if (!mesh.curves.count(spec.source)) {
        waiting.push_back(cp);
        continue;
      }
      if (MeshError e = copy_periodic_plan(model, spec, *cp, mesh); !e.ok()) return e;
    }
    if (waiting.size() == copies.size())
    {
      const int tag = waiting.front()->tag, source = periodic.at(tag).source;
      return make_error(MeshErrorKind::Invalid, tag, source, MeshProblem::PeriodicCycle, {tag, source});
    }
    copies.swap(waiting);
  }
  return {};
}

// The nodes of the vertices that move (vertex_moves) put at their curve's start.
void move_closed_curve_vertices(const geo::Model& model, const std::map<int, int>& curves_at, ModelMesh& mesh) {
  for (const auto& [tag, mc] : model.curves()) {
    if (!vertex_moves(curves_at, mc)) continue;
    MeshNode& n = mesh.nodes[mesh.vertex_node.at(mc.begin)];
    n.xyz = mc.shape->point(0);
    if (mc.shape->on_surface()) n.uv = mc.shape->eval_uv(0).p, n.has_uv = true;
  }
}

// The repair of crossing 1D meshes: the curves bounding or embedded in a surface (all
// with opt.repair_all_curves) grouped by the plane they are drawn in, each group's
// crossings repaired (repair_group); the first error.
MeshError repair_intersections(const geo::Model& model, const Mesh1dOptions& opt, ModelMesh& mesh, Mesh1dStats& st) {
  std::map<int, PlaneGroup> groups;  // geometry tag -> curves; 0: Euclidean z = const
  bool euclid_planar = true;
  std::optional<double> euclid_z;
  std::vector<int> in_surface;  // curves bounding or embedded in a surface
  for (const auto& [stag, s] : model.surfaces()) {
    for (int l : s.loops)
      if (const geo::ModelCurveLoop* loop = model.curve_loop(std::abs(l)))
        for (int c : loop->curves) in_surface.push_back(std::abs(c));
    in_surface.insert(in_surface.end(), s.embedded_curves.begin(), s.embedded_curves.end());
  }
  std::sort(in_surface.begin(), in_surface.end());
  for (const auto& [tag, mc] : model.curves()) {
    if (!opt.repair_all_curves && !std::binary_search(in_surface.begin(), in_surface.end(), tag)) continue;
    if (mesh.curves.at(tag).nodes.size() < 2) continue;  // collapsed: no edge to cross
    const int key = mc.shape->on_surface() ? mc.geometry : 0;
    if (key == 0) {
      for (std::uint32_t n : mesh.curves.at(tag).nodes) {
        if (!euclid_z) euclid_z = mesh.nodes[n].xyz.z;
        if (mesh.nodes[n].xyz.z != *euclid_z) euclid_planar = false;
      }
    }
    PlaneGroup& g = groups[key];
    g.geometry = key;
    g.curves.push_back(tag);
  }
  for (auto& [key, g] : groups) {
    if (key == 0 && !euclid_planar) continue;
    if (key == 0) g.z = euclid_z.value_or(0.0);
    MeshError e = repair_group(model, g, mesh, opt, st);
    if (!e.ok()) return e;
  }
  return {};
}

// The model points' nodes. Gmsh's leniency on coincident points: a curve between two
// distinct points at the same place whose control points are all there (a zero-length
// Line, a B-spline of repeated points) is collapsed: its two end points get one node and
// the curve no edge, so the loops through it stay closed (geo/model.cpp notes it where the
// curve is made). The points joined so share the node of the smallest tag (a union-find
// over the vertices). Returns the collapsed curves' tags, ascending.
std::vector<int> add_vertex_nodes(const geo::Model& model, ModelMesh& mesh) {
  std::map<int, int> joined;  // vertex tag -> a vertex it was joined to (smaller tag)
  // Each step goes to a smaller tag: at most as many steps as vertices.
  auto root_of = [&](int v) {
    for (auto it = joined.find(v); it != joined.end(); it = joined.find(v)) v = it->second;
    return v;
  };
  std::vector<int> collapsed;
  for (const auto& [tag, mc] : model.curves()) {
    if (!geo::collapses(model, mc)) continue;
    collapsed.push_back(tag);
    const int a = root_of(mc.begin), b = root_of(mc.end);
    if (a != b) joined[std::max(a, b)] = std::min(a, b);
  }
  for (const auto& [tag, v] : model.vertices()) {
    if (const int root = root_of(tag); root != tag) {  // the root's tag is smaller: made already
      mesh.vertex_node[tag] = mesh.vertex_node.at(root);
      continue;
    }
    const geo::SurfaceGeometry* g = v.geometry ? model.geometry(v.geometry) : nullptr;
    mesh.vertex_node[tag] = g ? mesh.add_node(v.xyz, v.uv) : mesh.add_node(v.xyz);
  }
  return collapsed;
}

}  // namespace

Mesh1dResult mesh_curves(const geo::Model& model, const Mesh1dOptions& opt) {
  Mesh1dResult res;
  ModelMesh& mesh = res.mesh;
  mesh.dim = 1;
  double bbox = opt.bbox_diag;
  if (!(bbox > 0)) bbox = model.bounding_box().diagonal();
  if (!(bbox > 0)) bbox = 1;
  const std::vector<int> collapsed = add_vertex_nodes(model, mesh);
  auto t0 = std::chrono::steady_clock::now();
  const std::map<int, int> curves_at = curves_at_vertices(model);
  StageEnd stage{opt.progress};
  stage.begin("1D", model.curves().size());
  std::vector<CurvePlan> plans = make_plans(model, opt, curves_at, collapsed);
  const int threads = resolve_thread_count(opt.threads);
  // First every curve's size integral, hence its node count: a count beyond the budget
  // is refused before any node is placed (a size of 1e-20 asks for 1e20 nodes).
  parallel_for_chunks(
      threads, plans.size(), 1,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) integrate_plan(model, opt, bbox, plans[i]);
      },
      [&](std::size_t done) { progress_update(opt.progress, done); });
  double total_nodes = 0;
  if (!check_node_budget(plans, opt, res, total_nodes)) return res;
  std::optional<ModelMesh> coarse;
  if (opt.max_elements > 0 && opt.coarse_check && total_nodes > opt.coarse_check_nodes)
    coarse = coarse_mesh(plans, opt, bbox, mesh, threads);
  plan_compounds(model, opt, plans);
  // The nodes of each curve (parameters and coordinates), in parallel; then numbered.
  // The coarse check (the faces' budgets, a serial triangulation) is job 0, beside the
  // curves' placement rather than before it: on one thread it runs first and a refusal
  // skips the placement, as before; on more the placement is done while it runs, and
  // thrown away if it refuses. Neither reads what the other writes. Beside it only up to
  // kOverlapNodes in all (about 50 bytes a node placed in vain on a refusal): the check is
  // there to refuse a boundary of millions of nodes before they are placed.
  std::atomic<bool> refused{false};
  if (coarse && (threads == 1 || total_nodes > kOverlapNodes)) {
    refused = !opt.coarse_check(*coarse);
    coarse.reset();
  }
  const std::size_t first_curve = coarse ? 1 : 0;
  parallel_for_chunks(threads, plans.size() + first_curve, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t job = begin; job < end; ++job) {
      if (job < first_curve) {
        if (!opt.coarse_check(*coarse)) refused = true;
        coarse.reset();
        continue;
      }
      if (refused) return;   // the check ran first (one thread, or too many nodes) and refused
      CurvePlan& cp = plans[job - first_curve];
      try {
        place_plan(model, opt, bbox, cp);
      } catch (...) {
        cp.thrown = std::current_exception();
      }
    }
  });
  if (refused) {
    res.error = make_error(MeshErrorKind::Stopped, 0, 0);
    return res;
  }
  res.error = number_nodes(model, opt, plans, mesh);
  if (!res.ok()) return res;
  stage.end();
  // The plans (each curve's size integral and nodes) are the mesh's now: freed, and their
  // heap given back, before the repair's arrays are made beside them (at 3 km on the full
  // GSHHG they made the peak of the repair, which was the run's; docs/kernel.md, "Memory").
  std::vector<CurvePlan>().swap(plans);
  release_free_memory();
  move_closed_curve_vertices(model, curves_at, mesh);
  res.stats.seconds_integrate = seconds_since(t0);
  if (opt.repair_intersections) {
    t0 = std::chrono::steady_clock::now();
    stage.begin("1D repair", 0);
    res.error = repair_intersections(model, opt, mesh, res.stats);
    if (!res.ok()) return res;
    res.stats.seconds_repair = seconds_since(t0);
  }
  if (opt.constraints && !opt.constraints->periodic_curves.empty()) {
    MeshError why;
    mesh.periodic = periodic_links(model, mesh, *opt.constraints, &why);
    if (!why.ok()) {
      res.error = std::move(why);
      return res;
    }
  }
  res.stats.curves = mesh.curves.size();
  res.stats.nodes = mesh.nodes.size();
  res.stats.edges = mesh.num_curve_edges();
  return res;
}

}  // namespace sm
