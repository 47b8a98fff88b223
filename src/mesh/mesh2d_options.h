// What 2D meshing is asked and what it answers: Mesh.Algorithm, the options of
// mesh_surfaces, its statistics and its result. Apart from mesh2d.h so that the steps of
// the face pipeline (face_work.h and the face_*.cpp files) see them without the pipeline.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "base/progress.h"
#include "field/boundary_layer.h"
#include "field/field.h"
#include "field/size_policy.h"
#include "mesh/mesh_constraints.h"
#include "mesh/mesh_error.h"
#include "mesh/mesh_note.h"
#include "mesh/mesh_stats.h"
#include "mesh/partition.h"

namespace sm {

/// Mesh.Algorithm with Gmsh's numbers.
/// InitialOnly (3): the boundary's constrained triangulation, with no node inserted.
enum class Mesh2dAlgorithm { MeshAdapt = 1, Automatic = 2, InitialOnly = 3, Del2d = 5, Frontal = 6 };

struct Mesh2dOptions {
  /// Del2d: refine_del2d; Frontal: refine_front2d; MeshAdapt: mesh_adapt from the
  /// boundary mesh; Automatic is Del2d. Frontal by default, as Gmsh 4.8.4's Mesh.Algorithm.
  Mesh2dAlgorithm algorithm = Mesh2dAlgorithm::Frontal;
  /// `MeshAlgorithm Surface{s} = n;`: the algorithm of those surfaces instead of `algorithm`.
  std::map<int, Mesh2dAlgorithm> surface_algorithm;
  field::SizePolicyOptions size;                 ///< Mesh.MeshSize*
  const field::SizeField* background = nullptr;  ///< Background Field, if any
  double bbox_diag = 0;                          ///< Gmsh's CTX::lc; <= 0: the model's bounding-box diagonal
  int smoothing = 1;                             ///< Mesh.Smoothing: Laplacian passes (meshadapt: per round)
  /// After smoothing (Mesh.Smoothing > 0), optimize_quality (mesh/modify/optimize.h) lifts
  /// the worst triangles: Mesh.QualityPass (stereomesh). del2d gets cheaper settings (only
  /// triangles below 0.75), keeping its speed; front2d and meshadapt the full pass.
  bool quality_pass = true;
  /// del2d / front2d resolve a triangle when circumradius / size <= this (measured in the
  /// plane with the size divided by the conformal factor: lambda on a PolarSphere,
  /// r cos(lat) in a Sphere's Mercator plane). 0: the algorithm's
  /// default (del2d 0.76, front2d refine.h's 1/sqrt2).
  double radius_limit = 0;
  /// Mesh.QualityFloor: after the quality pass, triangles with rho < this (in space) are
  /// worked on by raise_quality_floor (quality_floor.h): curve edges split at their
  /// curve's parameter midpoint (the curve's 1D mesh gets the node, so faces meshed later
  /// do too; a curve a face meshed before holds is left alone), interior points inserted,
  /// then the quality pass again; a face that would end worse is put back and done again
  /// never below its starting worst. Triangles at corners too sharp for it, and any left
  /// when the bounded work runs out, are reported in Mesh2dResult::notes.
  /// <= 0: off.
  double quality_floor = 0;
  /// front2d refuses the points Gmsh 4.8.4 refuses (RefineOptions::gmsh_rejection): too
  /// close to a node or to a boundary edge. On for flat models, where a script should get
  /// Gmsh's triangle counts; off on the sphere, whose meshes it would coarsen near coasts.
  bool gmsh_rejection = false;
  std::uint32_t max_vertices_per_face = 0xFFFFFFF0u;
  /// `BoundaryLayer Field = n;`: the layers built along their curves before the rest of
  /// each face is meshed (face_layer.h); null: none. A face with layers gets no quality
  /// floor (the floor would split the layers' edges; Gmsh has none).
  const std::vector<field::BoundaryLayerParams>* boundary_layers = nullptr;
  int boundary_layer_fan_elements = 5;  ///< Mesh.BoundaryLayerFanElements (per half turn)
  /// Mesh.MaxElements: a face whose estimated triangle count (estimate_triangles() on its
  /// recovered boundary triangulation, before any refinement) is over this is a
  /// LimitExceeded error; <= 0: no limit.
  double max_elements = 0;
  /// Threads for faces refined in parts and for smoothing (General.NumThreads /
  /// Mesh.MaxNumThreads2D); <= 0: the hardware's. The mesh does not depend on it;
  /// meshadapt is serial.
  int threads = 1;
  /// When and how del2d / front2d faces are refined in parts (partition.h).
  PartitionOptions partition;
  /// Told "2D" with one unit per face and, inside a face refined in parts, a nested
  /// "2D refine" with one unit per part; a del2d / front2d face refined in one piece and
  /// estimated at 65536 triangles or more gets a nested "2D refine" in estimated
  /// triangles instead. Reported from the calling thread only; null: nobody listens.
  Progress* progress = nullptr;
  /// Transfinite surfaces (filled by transfinite_surface.h instead of the algorithm, also
  /// a filling `Surface`) and recombined ones (their triangles paired by recombine.h
  /// after the quality passes). Null: none.
  const MeshConstraints* constraints = nullptr;
};

struct Mesh2dStats {
  std::uint64_t faces = 0, triangles = 0, new_nodes = 0;
  std::uint64_t quads = 0, transfinite_faces = 0;  // quadrangles made; faces filled transfinite
  std::uint64_t inserted = 0, rejected = 0, size_evaluations = 0;
  std::uint64_t partitioned_faces = 0, parts = 0;  // faces refined in parts, their parts
  std::uint64_t estimated_triangles = 0;           // of those faces, from their coarse meshes
  double seconds_boundary = 0;                     // Delaunay of the boundary nodes, edge recovery, holes
  double seconds_refine = 0;
  double seconds_smooth = 0;
  double seconds_optimize = 0;                             // optimize_quality
  double seconds_floor = 0;                                // the quality floor (its quality pass included)
  std::uint64_t floor_curve_splits = 0, floor_points = 0;  // what the floor inserted
  double seconds_output = 0;                               // nodes mapped to 3D, triangles oriented
};

struct Mesh2dResult {
  /// A failure names the surface first, then the curves involved: its problem, the
  /// surface, its numbers and place (mesh_error.h).
  MeshError error;
  /// The warnings, in the order the faces were meshed: islands left out, a boundary off
  /// its plane, and surfaces left below Mesh2dOptions::quality_floor (sharp corners, work
  /// bounded), each about one surface (mesh_note.h).
  std::vector<MeshNote> notes;
  Mesh2dStats stats;
  /// Per meshed surface (tag order), the size its mesher aimed at, at 3D points (the
  /// points go radially onto a sphere): the size policy with the background field and
  /// the extension from the boundary (Mesh.MeshSizeExtendFromBoundary), as on the surface,
  /// for mesh_stats. Valid while opt.background lives; each function keeps its own
  /// scratch, so call it from one thread at a time.
  std::vector<SurfaceSize> target_sizes;
  bool ok() const { return error.ok(); }
};

}  // namespace sm
