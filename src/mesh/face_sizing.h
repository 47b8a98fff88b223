// The target size of a face in its plane: the size policy with the background field and
// (Mesh.MeshSizeExtendFromBoundary) the boundary sizes extended into the face, for the
// refiners (divided by the conformal factor) and for the statistics after meshing.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "field/field.h"
#include "field/size_policy.h"
#include "geo/model.h"
#include "mesh/cdt.h"
#include "mesh/face_plane.h"
#include "mesh/mesh_stats.h"
#include "mesh/model_mesh.h"
#include "mesh/triangulation.h"

namespace sm {

/// What a face's target size depends on (the one definition, for the refiners and for the
/// statistics after meshing): the size policy with the background field and, with
/// Mesh.MeshSizeExtendFromBoundary, the extension of the boundary sizes into the face: the
/// recovered boundary triangulation `bg` and per vertex the mean length of its boundary
/// edges (inf: none). Outlives its face's mesher when kept in Mesh2dResult::target_sizes.
struct FaceSizing {
  int tag = 0;
  double bbox = 0;
  field::SizePolicyOptions size;
  const field::SizeField* background = nullptr;
  FacePlane plane;
  TriangleStore bg;
  std::vector<double> bsize;
};

/// With f.size.extend_from_boundary set: f.bg = `recovered` (the face's boundary
/// triangulation after edge recovery, before hole removal: the walk that locates a point
/// must not stop at a hole; its first `fixed_count` vertices the boundary and embedded
/// nodes `global[v]`) and f.bsize per such vertex the mean
/// length of its `edges`. An embedded point on no edge keeps the size its model vertex
/// prescribes (Mesh.MeshSizeFromPoints), else gets none (inf). `coarse`: the boundary is
/// the element budget's coarse one, whose curves carry their 1D sizes (CurveMesh::h):
/// those, not its long edges, are what the real boundary would extend.
void set_boundary_sizes(FaceSizing& f, TriangleStore recovered, std::uint32_t fixed_count,
                        std::span<const Edge> edges, std::span<const std::uint32_t> global, const ModelMesh& mesh,
                        const geo::Model& model, bool coarse);

/// The target size at batches of points of the face's plane (FaceSizing). Holds its own
/// scratch and walk hint, so each part of a partitioned face gets its own and none writes
/// another's; the face data it reads is not modified while it lives.
class PlaneSizes {
 public:
  /// What operator() and on_surface give: the whole target size, or its two halves for
  /// refiners that size triangles by their vertices (RefineOptions::vertex_size_at): the
  /// size without the extension from the boundary, and the extension alone (inf where
  /// there is none, or with Mesh.MeshSizeExtendFromBoundary = 0).
  enum class Part { All, WithoutExtension, ExtensionOnly };
  /// evaluations: counts the points evaluated (shared by the parts), may be null.
  explicit PlaneSizes(const FaceSizing& f, std::atomic<std::uint64_t>* evaluations = nullptr, Part part = Part::All)
      : f_(f), evaluations_(evaluations), part_(part) {}
  /// h[i] = the size in the plane at p[i]: the size on the surface divided by lambda.
  void operator()(std::span<const Vec2> p, std::span<double> h);
  /// h[i] = the size on the surface (3D lengths) at p[i].
  void on_surface(std::span<const Vec2> p, std::span<double> h);

 private:
  std::optional<double> boundary_size(Vec2 p);

  const FaceSizing& f_;
  std::atomic<std::uint64_t>* evaluations_;
  Part part_ = Part::All;
  TriId hint_;
  std::uint32_t walk_turn_ = 0;
  std::vector<Vec3> pts3_;
  std::vector<double> field_;
};

/// The face's target size at 3D points for the statistics: each point is taken to the
/// face's plane (radially onto a sphere first) and given PlaneSizes::on_surface there.
SizeAt3 target_size_fn(std::shared_ptr<const FaceSizing> sizing);

}  // namespace sm
