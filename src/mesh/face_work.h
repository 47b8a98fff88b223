// The state of one face in the 2D pipeline (mesh2d.cpp): what the steps (face_boundary,
// face_boundary_mesh, face_refine, face_smooth, face_floor, face_output, face_transfinite)
// read and fill in turn. Each step is a free function over a FaceWork; none includes
// mesh2d.h, and the state knows no step.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/vec.h"
#include "geo/model.h"
#include "mesh/cdt.h"
#include "mesh/face_plane.h"
#include "mesh/face_sizing.h"
#include "mesh/mesh2d_options.h"
#include "mesh/model_mesh.h"
#include "mesh/triangulation.h"

namespace sm {

/// A global node that is no local vertex of the face (FaceWork::local_of, ::global).
inline constexpr std::uint32_t kNoLocal = 0xFFFFFFFFu;

/// One chain of global nodes with the curve of each edge: closed (a loop; first node not
/// repeated, edge i joins nodes i and i+1 mod n) or open (an embedded curve).
struct FaceChain {
  std::vector<std::uint32_t> nodes;
  std::vector<int> edge_curve;
};

/// One face being meshed, from its boundary loops to its elements in the model mesh.
/// Failures go to res.error (fail()), warnings to res.notes.
struct FaceWork {
  /// scratch (local_of): global node -> local vertex, all kNoLocal; left so again on destruction.
  FaceWork(const geo::Model& the_model, ModelMesh& the_mesh, const Mesh2dOptions& options, double diag,
           Mesh2dResult& result, std::vector<std::uint32_t>& scratch, int surface);
  ~FaceWork();
  FaceWork(const FaceWork&) = delete;
  FaceWork& operator=(const FaceWork&) = delete;

  /// Sets the error: `problem` with its numbers on this surface, then `curves`, the place.
  /// Returns false.
  bool fail(MeshProblem problem, std::initializer_list<long long> numbers = {},
            std::optional<Vec3> where = std::nullopt, std::initializer_list<int> curves = {});
  /// fail(problem) with a sub-step's own words as its reason.
  bool fail_because(MeshProblem problem, std::string reason);
  /// "lon X, lat Y" of a point of the face (on a geometry), else "(x, y, z)".
  std::string where_text(Vec3 p) const;
  /// A point of the face as a note's place: in space, and in degrees on a geometry.
  MeshPlace place_of(Vec3 p) const;
  /// Whether the surface's triangles are paired into quadrangles (recombine.h).
  bool recombined() const;

  const geo::Model& model;
  ModelMesh& mesh;
  const Mesh2dOptions& opt;
  double bbox;
  Mesh2dResult& res;
  int tag;
  /// Only up to the element budget (check_face_budgets): no refinement, no output.
  bool estimate_only = false;
  FacePlane plane;
  std::vector<FaceChain> chains;          // [0] outer, then holes
  std::vector<std::uint32_t> emb_points;  // global nodes
  std::vector<FaceChain> emb_curves;      // open chains (edge i joins nodes i, i+1)
  std::vector<std::uint32_t> global;      // local vertex -> global node
  std::vector<std::uint32_t>& local_of;   // global node -> local vertex (shared scratch)
  std::vector<Edge> edges;                // boundary and embedded edges (local vertices)
  std::vector<int> edge_curve;            // the curve of each
  std::uint32_t fixed_count = 0;          // local vertices [0, fixed_count): the input nodes
  TriangleStore tri;                      // the face's triangulation in its plane
  TriangleStore hull;                     // tri before hole removal (extension from the boundary)
  std::shared_ptr<FaceSizing> sizing = std::make_shared<FaceSizing>();
  std::atomic<std::uint64_t> size_evaluations{0};
  bool smoothed = false;  // meshadapt smooths in each of its rounds
  /// The boundary layers' elements (face_layer.h), global nodes, counter-clockwise in the
  /// plane, and the nodes they added; chains and emb_curves then bound the rest.
  std::vector<std::array<std::uint32_t, 3>> layer_triangles;
  std::vector<std::array<std::uint32_t, 4>> layer_quads;
  std::vector<std::uint32_t> layer_nodes;
  bool has_layers() const { return !layer_triangles.empty() || !layer_quads.empty(); }
};

}  // namespace sm
