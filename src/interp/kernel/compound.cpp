// Gmsh 4.8.4's compound statements (Parser/Gmsh.y, Geo/GModelIO_GEO.cpp):
//   `Compound Curve{...};` / `Compound Surface{...};`: meshing constraints, kept in
//     KernelState::constraints for the mesher (mesh/compound_curve.h, compound_surface.h);
//   `Compound Spline(t) = {curves} Using n;` / `Compound BSpline(...)`: a new curve
//     through points sampled on the curves (GEO_Internals::_addCompoundSpline): the first
//     curve's begin point, then n - 1 new points per curve at equal steps of its
//     parameter (each a new point tag, its size interpolated between the curve's end
//     points' sizes), then the curve's end point.
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "interp/interpreter.h"
#include "interp/kernel/compound.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/provenance.h"
#include "mesh/compound_curve.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

void report_missing_compound(Interpreter& in, SourceRange at, const char* what, int tag) {
  in.diags().report(at, Diag::GmshCompatCompoundMissing, what, tag);
}

}  // namespace

void exec_compound_stmt(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  const auto& n = std::get<CompoundStmt>(s.node);
  KernelState& k = in.kernel();
  const geo::Model& m = k.model;
  if (n.ent != EntityKind::Curve && n.ent != EntityKind::Surface) {
    check_stmt_exprs(in, id);
    in.not_supported_stmt(id, fmt::format("Compound {}", n.ent == EntityKind::Volume ? "Volume" : "Point"));
    return;
  }
  const bool curves = n.ent == EntityKind::Curve;
  std::vector<int> group;
  for (int t : eval_tags(in, n.tags)) {
    const int a = std::abs(t);
    if (curves ? !m.curve(a) : !m.surface(a)) {
      report_missing_compound(in, s.range, curves ? "curve" : "surface", a);
      continue;
    }
    group.push_back(a);
  }
  if (group.empty()) return;
  if (curves && group.size() > 1 && chain_compound(m, group).empty())
    in.diags().report(s.range, Diag::GmshCompatCompoundNotChain);
  (curves ? k.constraints.compound_curves : k.constraints.compound_surfaces).push_back(std::move(group));
}

std::optional<geo::DimTag> exec_compound_spline(Interpreter& in, const Stmt& s, const CurveStmt& n) {
  KernelState& k = in.kernel();
  geo::Model& m = k.model;
  const int tag = eval_tag(in, n.tag);
  const std::vector<int> curves = eval_tags(in, n.points);
  const double using_n = in.eval_number(n.using_n);
  const SourceRange at_n = in.ast().expr(n.using_n).range;
  if (!std::isfinite(using_n) || std::fabs(using_n) > 1e6)
    in.fail(at_n, Diag::CompoundIntervalsNotNumber, using_n);
  const int intervals = static_cast<int>(using_n);   // Gmsh: (int)
  if (intervals < 0)
    in.fail(at_n, Diag::CompoundIntervalsNegative, intervals);
  if (curves.empty())
    in.fail(in.ast().expr(n.points).range, Diag::CompoundNoCurve);
  if (tag == 0) in.fail(s.range, Diag::CompoundTagZero);
  if (m.curve(std::abs(tag))) in.fail(s.range, Diag::CompoundCurveExists, tag);
  for (int c : curves)
    if (const geo::ModelCurve* mc = m.curve(std::abs(c)); !mc || !mc->shape)
      in.fail(in.ast().expr(n.points).range, Diag::GeoNoSuchCurve, std::abs(c));
  std::vector<int> points;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    // Curve -c is c run backwards (Gmsh's reversed copy of every curve).
    const geo::ModelCurve& mc = *m.curve(std::abs(curves[i]));
    const bool rev = curves[i] < 0;
    const int beg = rev ? mc.end : mc.begin, end = rev ? mc.begin : mc.end;
    if (i == 0) points.push_back(beg);
    const double lc0 = m.vertex(beg)->lc, lc1 = m.vertex(end)->lc;
    for (int j = 1; j < intervals; ++j) {
      const double u = static_cast<double>(j) / intervals;
      const Vec3 p = m.curve(std::abs(curves[i]))->shape->point(rev ? 1 - u : u);
      const int pt = m.new_point_tag();
      const geo::GeoStatus st = m.add_point(pt, p, (1 - u) * lc0 + u * lc1);
      if (!st) fail_geo(in, s.range, st.error());
      record_created(k, 0, pt, s.range);
      points.push_back(pt);
    }
    points.push_back(end);
  }
  const geo::CurveKind kind = n.kind == CurveKind::CompoundBSpline ? geo::CurveKind::BSpline : geo::CurveKind::Spline;
  const geo::GeoStatus st = m.add_curve(tag, kind, points);
  if (!st) fail_geo(in, s.range, st.error());
  return geo::DimTag{1, tag};
}

}  // namespace sm::interp
