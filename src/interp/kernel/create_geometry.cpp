// `CreateGeometry;` (Gmsh 4.8.4's GModel::createGeometryOfDiscreteEntities): the discrete
// curves and surfaces of a merged mesh get a geometry made from their mesh, so that the 1D
// and 2D meshers remesh them, with their tags. A curve's geometry is the polyline of its
// nodes (Gmsh's discreteEdge parametrisation by node index); a flat surface's is its plane
// (Gmsh: "is planar, simplifying parametrization"), bounded by the discrete curves along its
// mesh boundary, with the discrete curves inside it embedded. A curved surface (a 3D
// reparametrisation) is not supported yet.
#include <string>
#include <vector>

#include "interp/interpreter.h"
#include "interp/kernel/dispatch.h"
#include "interp/kernel/geometry_shapes.h"
#include "interp/provenance.h"
#include "mesh/discrete_surface_boundary.h"

namespace sm::interp {

using namespace sm::lang;

namespace {

// The discrete curves not yet given a geometry, whose nodes Merge recorded.
std::vector<int> curves_without_geometry(const KernelState& k) {
  std::vector<int> out;
  for (const auto& [tag, c] : k.model.curves())
    if (c.discrete && !c.has_geometry && k.discrete.curve_nodes.count(tag)) out.push_back(tag);
  return out;
}

// Discrete surface `tag` as the plane surface its boundary curves enclose.
void give_geometry_to_surface(Interpreter& in, int tag, const std::vector<int>& curves, SourceRange at) {
  KernelState& k = in.kernel();
  const DiscreteSurfaceBoundary b = discrete_surface_boundary(k.discrete, tag, curves);
  using Problem = DiscreteSurfaceBoundary::Problem;
  switch (b.problem) {
    case Problem::None: break;
    case Problem::NotPlanar: in.fail(at, Diag::CreateGeometryNotPlanar, tag, b.node_a, b.distance);
    case Problem::EdgeOnNoCurve: in.fail(at, Diag::CreateGeometryEdgeOnNoCurve, tag, b.node_a, b.node_b);
    case Problem::CurvePartlyIn: in.fail(at, Diag::CreateGeometryCurvePartlyIn, tag, b.curve);
  }
  if (const geo::GeoStatus st = k.model.add_surface_of_discrete_mesh(tag, b.loops); !st) fail_geo(in, at, st.error());
  if (!b.inner_curves.empty())
    if (const geo::GeoStatus st = k.model.embed(1, b.inner_curves, tag); !st) fail_geo(in, at, st.error());
  record_created(k, 2, tag, at);
}

}  // namespace

void exec_create_geometry(Interpreter& in, StmtId id) {
  const Stmt& s = in.ast().stmt(id);
  const SourceRange at = s.range;
  KernelState& k = in.kernel();
  const std::vector<int> curves = curves_without_geometry(k);
  if (curves.empty() && k.discrete.surfaces.empty()) {
    in.diags().report(at, Diag::CreateGeometryNothing);
    return;
  }
  // Surfaces first: their boundaries are found on the curves' mesh nodes.
  for (const auto& [tag, surface] : k.discrete.surfaces) give_geometry_to_surface(in, tag, curves, at);
  k.discrete.surfaces.clear();
  for (int c : curves) {
    if (const geo::GeoStatus st = k.model.give_geometry_to_discrete_curve(c); !st) fail_geo(in, at, st.error());
    k.discrete.curve_nodes.erase(c);   // its mesh is the 1D mesher's now, no longer the file's
  }
  report_compat_notes(in, at);
}

}  // namespace sm::interp
