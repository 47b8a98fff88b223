// The 2D mesher's warnings as values: what it left out or did otherwise than asked, with
// the surface, the numbers and the place, never a sentence. The interpreter words each
// kind (interp/kernel/mesh_note_words.cpp), as it does mesh_error.h's failures.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/vec.h"
#include "geo/sphere.h"

namespace sm {

/// Where a note points: the point in space and, on a sphere geometry, its longitude and
/// latitude in degrees (then shown instead of x, y, z).
struct MeshPlace {
  Vec3 xyz{};
  bool on_sphere = false;
  geo::LonLat lonlat{};
};

/// A boundary corner too sharp for Mesh.QualityFloor: its angle (degrees) and where.
struct MeshNoteCorner {
  double degrees = 0;
  MeshPlace place{};
};

/// What a note says; each kind reads the MeshNote members listed beside it (and surface).
enum class MeshNoteKind {
  /// Hole loops whose closed curves got fewer than 3 mesh edges, left out of the face:
  /// loops (all of them), place (the largest island's).
  IslandsLeftOut,
  /// A Plane Surface's boundary off its plane by more than Geometry.Tolerance (but within
  /// the bound Gmsh checks), meshed in that plane: distance, relative (to the model's
  /// size), place (the farthest point).
  BoundaryOffPlane,
  /// Triangles left below Mesh.QualityFloor at boundary corners too sharp for it: count,
  /// floor, sharp_limit_degrees, corners (all of them, in the floor's order).
  FloorSharpCorners,
  /// Triangles still below Mesh.QualityFloor after its bounded work: count, floor,
  /// rounds, new_points, work_budget (> 0: the budget ran out), worst_rho, place (the
  /// worst triangle's centroid).
  FloorStillBelow,
  /// The floor left more triangles below it (or a worse one) than the face had, so the
  /// face was put back: count (after the floor), count_before, floor, rounds, new_points.
  FloorPutBack,
  /// An internal error of the floor (a walk that did not end); the face was put back as
  /// it was before the floor: fault (what failed), place.
  FloorFault,
};

/// The kind's name for tools that print notes without the language (tests/bench, tests/fuzz).
inline const char* mesh_note_kind_name(MeshNoteKind kind) {
  switch (kind) {
    case MeshNoteKind::IslandsLeftOut: return "islands left out";
    case MeshNoteKind::BoundaryOffPlane: return "boundary off its plane";
    case MeshNoteKind::FloorSharpCorners: return "below the quality floor at sharp corners";
    case MeshNoteKind::FloorStillBelow: return "still below the quality floor";
    case MeshNoteKind::FloorPutBack: return "quality floor undone";
    case MeshNoteKind::FloorFault: return "quality floor internal error";
  }
  return "?";
}

/// One warning of the 2D mesher about one surface.
struct MeshNote {
  MeshNoteKind kind = MeshNoteKind::IslandsLeftOut;
  int surface = 0;  ///< as in the meshed model (a Compound Surface's union has its own tag)
  MeshPlace place{};
  std::uint64_t count = 0;
  std::uint64_t count_before = 0;
  double floor = 0;  ///< Mesh.QualityFloor
  double sharp_limit_degrees = 0;
  std::vector<MeshNoteCorner> corners{};
  std::vector<int> loops{};
  std::uint32_t rounds = 0;
  std::uint64_t new_points = 0;
  std::uint64_t work_budget = 0;
  double worst_rho = 0;
  double distance = 0;  ///< model units
  double relative = 0;  ///< distance over the model's bounding-box diagonal
  std::string fault{};

  /// Whether the note is the quality floor's (reported as mesh-quality-floor, after the others).
  bool about_floor() const { return kind >= MeshNoteKind::FloorSharpCorners; }
};

}  // namespace sm
