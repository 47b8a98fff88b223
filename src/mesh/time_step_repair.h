// Mesh.MinTimeStep after meshing: the nodes that make a triangle's Courant step too short
// (a lone coast node in one triangle, the short side of a sliver) are removed by collapsing
// the triangle's shortest edge, as mesh/modify/collapse.h does on a TriangleStore, here on
// the ModelMesh the writers read (its curve meshes kept in step).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "mesh/model_mesh.h"
#include "mesh/time_step.h"

namespace sm {

/// One node removed: where it was, and the step of the triangle it held back.
struct StepRemoval {
  Vec3 where;
  int surface = 0;
  double edge = 0;         ///< the collapsed edge (m)
  double step = 0;         ///< the step of the triangle before (s)
};

struct StepRepairResult {
  std::vector<StepRemoval> removed;
  std::size_t rounds = 0;
};

/// Rounds (at most `max_rounds`, each one pass over the triangles) of collapses of the
/// shortest edge of every triangle whose step is under `min_dt`, at most `max_collapses`
/// in all. A collapse moves node v onto its neighbour w and is made only when v is no
/// model vertex, v's triangles lie in one surface without quadrangles, v is on no curve or
/// inside one curve with w its neighbour along it (the coast then runs straight from w on),
/// the link condition holds, every triangle left keeps its orientation (exact orient2d on
/// the nodes' (u,v)), and the smallest step of the triangles changed grows. Deterministic:
/// triangles are taken by increasing step, ties by surface tag and index.
StepRepairResult repair_short_steps(ModelMesh& mesh, std::span<const double> node_depth, double min_dt,
                                    const TimeStepOptions& opt, std::size_t max_rounds = 8,
                                    std::size_t max_collapses = 100000);

}  // namespace sm
