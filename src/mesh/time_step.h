// The time step an explicit ocean model can take on a mesh at Courant number 1:
// dt = min over triangles of (shortest edge) / sqrt(g H), H the deepest of the
// triangle's three node depths (the fastest gravity wave crossing it).
#pragma once

#include <cstdint>
#include <span>

#include "base/vec.h"
#include "mesh/model_mesh.h"

namespace sm {

struct TimeStepOptions {
  double gravity = 9.81;   ///< m/s^2
  double min_depth = 0;    ///< node depths are raised to at least this (m)
  /// Edges are great-circle arcs on this sphere when radius > 0 (the model's
  /// PolarSphere), else straight chords.
  Vec3 centre{};
  double radius = 0;
};

struct TimeStep {
  bool valid = false;      ///< false: no triangle with a positive depth
  double dt = 0;           ///< seconds
  double edge = 0;         ///< the shortest edge of the limiting triangle (m)
  double depth = 0;        ///< its H (m)
  int surface = 0;         ///< its surface tag
  Vec3 where{};            ///< its centroid
  bool has_lonlat = false; ///< on a sphere: lon/lat of the centroid (degrees)
  double lon = 0, lat = 0;
};

/// dt over every surface triangle of `mesh`; node_depth[v] is the depth of node v
/// (positive down, metres). Triangles whose H is not positive (dry land) are skipped.
/// Ties go to the first triangle in surface-tag order, so the answer is deterministic.
TimeStep courant_time_step(const ModelMesh& mesh, std::span<const double> node_depth,
                           const TimeStepOptions& opt = {});

}  // namespace sm
