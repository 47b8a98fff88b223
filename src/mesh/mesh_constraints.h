// The structured-meshing constraints of a script (Gmsh's meshAttributes): transfinite
// curves and surfaces, recombined surfaces, the recombination algorithm. Plain data: the
// interpreter fills it from `Transfinite ...;`, `Recombine ...;` and Mesh.* options, the
// 1D and 2D meshers read it.
#pragma once

#include <map>
#include <set>
#include <utility>
#include <vector>

namespace sm {

/// Gmsh's `Using Progression | Bump | Beta` (meshGEdge.cpp's typeTransfinite 1, 2, 3).
enum class TransfiniteLaw { Progression = 1, Bump = 2, Beta = 3 };

/// `Transfinite Curve {c} = nodes Using law coef;` on the curve's own direction: a
/// negative tag in the statement sets `reversed` (the law runs from the curve's end).
struct TransfiniteCurveSpec {
  int nodes = 2;              // at least 2, as Gmsh
  TransfiniteLaw law = TransfiniteLaw::Progression;
  double coef = 1.0;          // |coef| as written; 1: equal spacing
  bool reversed = false;
};

/// `Transfinite Surface {s} = {corners} Left|Right|...;`: which diagonal splits each
/// grid cell into two triangles (Gmsh's transfiniteArrangement: Left -1, Right 1,
/// Alternate / AlternateRight 2, AlternateLeft -2).
enum class TriangleArrangement { Left = -1, Right = 1, AlternateRight = 2, AlternateLeft = -2 };

struct TransfiniteSurfaceSpec {
  std::vector<int> corners;   // 3 or 4 model vertex tags; empty: the loop's curve ends
  TriangleArrangement arrangement = TriangleArrangement::Left;
};

/// `Periodic Curve{target} = {source} [transform];` (Gmsh's meshMaster of the target):
/// the target's mesh is a copy of its source's, as many nodes, run in `orientation`
/// (+1: the target's begin matches the source's begin, -1: the source's end). `affine`:
/// empty (the nodes keep their parameters, Gmsh's "identical parametrisations") or the
/// 16 numbers, row by row, of the 4x4 map from the source onto the target.
struct PeriodicCurveSpec {
  int source = 0;   // > 0
  int orientation = 1;
  std::vector<double> affine;
};

/// A model point made periodic by its curve's statement: its node corresponds to its
/// master's (Gmsh writes those pairs too, with the curve's transform).
struct PeriodicPointSpec {
  int master = 0;
  std::vector<double> affine;
};

/// `Periodic Surface target {curves} = source {curves} [transform];` (Gmsh's meshMaster
/// of the target surface): the target's mesh is a copy of its source's by `affine` (16
/// numbers row by row, given or inferred), its boundary curves' copies being periodic
/// curves of their own.
struct PeriodicSurfaceSpec {
  /// A boundary curve of the target with its counterpart on the source's, and whether
  /// their nodes run alike (+1) or reversed (-1); a curve may be its own counterpart.
  struct CurvePair {
    int target = 0, source = 0;   // > 0
    int orientation = 1;
  };
  int source = 0;   // > 0
  std::vector<double> affine;
  /// The target's boundary curves, then its embedded curves, each with its counterpart.
  std::vector<CurvePair> curves;
  /// Embedded points of the target with their counterparts on the source (target, source):
  /// their nodes are no curve's, so the copy pairs them on their own.
  std::vector<std::pair<int, int>> points;
};

/// Mesh.RecombinationAlgorithm 0 (simple) and 1 (blossom-quality; see recombine.h).
enum class RecombineAlgorithm { Simple = 0, Matching = 1 };

struct MeshConstraints {
  std::map<int, TransfiniteCurveSpec> curves;       // curve tag (> 0) -> its law
  std::map<int, TransfiniteSurfaceSpec> surfaces;   // surface tag -> its corners
  std::set<int> recombine;                          // `Recombine Surface{...};`
  bool recombine_all = false;                       // Mesh.RecombineAll
  RecombineAlgorithm algorithm = RecombineAlgorithm::Matching;
  /// `MeshAlgorithm Surface{s} = n;`: Gmsh's algorithm number of those surfaces.
  std::map<int, int> surface_algorithm;
  /// `Compound Curve{...};` and `Compound Surface{...};`: each group meshed as one
  /// (mesh/compound_curve.h, mesh/compound_surface.h), tags as written.
  std::vector<std::vector<int>> compound_curves, compound_surfaces;
  /// `Periodic Curve`: target curve tag -> its source; target point -> its master (the
  /// last statement naming a point wins, as in Gmsh).
  std::map<int, PeriodicCurveSpec> periodic_curves;
  std::map<int, PeriodicPointSpec> periodic_points;
  /// `Periodic Surface`: target surface tag -> its source.
  std::map<int, PeriodicSurfaceSpec> periodic_surfaces;

  bool recombines(int surface) const { return recombine_all || recombine.count(surface) > 0; }
  bool empty() const {
    return curves.empty() && surfaces.empty() && recombine.empty() && !recombine_all && surface_algorithm.empty() &&
           compound_curves.empty() && compound_surfaces.empty() && periodic_curves.empty() &&
           periodic_surfaces.empty();
  }
};

}  // namespace sm
