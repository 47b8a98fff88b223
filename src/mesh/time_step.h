// The time step an explicit ocean model can take on a mesh at Courant number 1:
// dt = min over triangles of (shortest edge) / sqrt(g H), H the deepest of the
// triangle's three node depths (the fastest gravity wave crossing it).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

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
  /// The 1% quantile of the per-triangle steps (the step of the triangle at rank
  /// floor(0.01 (n - 1)) in increasing order): how far the few worst stand out.
  double q01 = 0;
  std::size_t wet = 0;     ///< triangles counted (positive depth)
};

/// Each wet triangle's Courant step (seconds), in the order of courant_time_step's walk
/// (surfaces by tag, triangles in order); dry triangles get +infinity.
std::vector<double> triangle_time_steps(const ModelMesh& mesh, std::span<const double> node_depth,
                                        const TimeStepOptions& opt = {});

/// The length of edge a-b as the time step measures it (arc on the sphere, else chord).
double time_step_edge_length(Vec3 a, Vec3 b, const TimeStepOptions& opt);

/// Lon/lat (degrees) of x about opt.centre, the sphere's axis as the polar axis.
void time_step_lonlat(Vec3 x, const TimeStepOptions& opt, double& lon, double& lat);

/// The Courant step of triangle (a, b, c) with node depths da, db, dc; +infinity when dry.
double triangle_time_step(Vec3 a, Vec3 b, Vec3 c, double da, double db, double dc, const TimeStepOptions& opt);

/// dt over every surface triangle of `mesh`; node_depth[v] is the depth of node v
/// (positive down, metres). Triangles whose H is not positive (dry land) are skipped.
/// Ties go to the first triangle in surface-tag order, so the answer is deterministic.
TimeStep courant_time_step(const ModelMesh& mesh, std::span<const double> node_depth,
                           const TimeStepOptions& opt = {});

}  // namespace sm
