// The one failure shape of the mesh kernel (1D and 2D meshers): a kind, the model entities
// involved (the interpreter maps them back to the statements that created them, as it
// does for geo/error.h), a message and a place; never thrown, never printed.
#pragma once

#include <string>
#include <vector>

#include "base/vec.h"
#include "geo/sphere.h"

namespace sm {

/// LimitExceeded: more nodes or triangles than Mesh.MaxElements (or kMaxCurveNodes);
/// Stopped: Mesh1dOptions::coarse_check said no.
enum class MeshErrorKind { None, Failed, Intersection, DuplicatePoint, Invalid, NoProgress, LimitExceeded, Stopped };

/// A model entity named by an error: its dimension (1 curve, 2 surface) and tag.
struct MeshEntity {
  int dim = 0;
  int tag = 0;
  friend bool operator==(MeshEntity a, MeshEntity b) { return a.dim == b.dim && a.tag == b.tag; }
};

struct MeshError {
  MeshErrorKind kind = MeshErrorKind::None;
  /// The failing entity first (the curve of a 1D error, the surface of a 2D one), then
  /// the others involved (the second curve of a crossing, the curves of a surface's
  /// crossing boundary edges); each once.
  std::vector<MeshEntity> entities;
  std::string message;
  Vec3 xyz;                  ///< where, in space (when known)
  bool has_lonlat = false;   ///< on a sphere geometry: where, in degrees
  geo::LonLat where;
  double count = 0;          ///< LimitExceeded: the nodes or triangles asked
  double limit = 0;          ///< LimitExceeded: the limit they exceed
  bool all_curves = false;   ///< 1D LimitExceeded: count is the sum over the curves

  bool ok() const { return kind == MeshErrorKind::None; }
  /// The tag of entities[i], 0 when there is none.
  int tag(std::size_t i = 0) const { return i < entities.size() ? entities[i].tag : 0; }
  /// Appends an entity unless it is already named (tags <= 0 name nothing).
  void add_entity(int dim, int tag) {
    const MeshEntity e{dim, tag};
    if (tag <= 0) return;
    for (const MeshEntity& x : entities)
      if (x == e) return;
    entities.push_back(e);
  }
};

}  // namespace sm
