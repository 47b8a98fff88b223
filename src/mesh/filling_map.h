// The plane of a non-planar filling Surface (docs/kernel.md, "Meshing faces"): the
// parameters (u, v) of its transfinite patch (geo/surface_filling.h) under the affine map
// p = L (u, v) with L^T L the patch's mean metric J^T J (L upper triangular, Cholesky), so
// that lengths in p are lengths on the surface on average: a patch whose map is sheared
// or stretched alike everywhere becomes near conformal. Gmsh 4.8.4 meshes such a face in
// (u, v) with the metric of the map; here the mesh is isotropic in p with the size divided
// by the local stretch sqrt|X_x x X_y| (FacePlane::lambda), which keeps the triangle count
// of the metric mesh (sizes measured in 3D) though not the shapes where the map varies far
// from its mean. Immutable once built: the sizing reads it from several threads.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "base/vec.h"
#include "geo/surface_filling.h"

namespace sm {

class FillingMap {
 public:
  /// `patch` of 3 or 4 sides; its mean metric fixes the plane (the mean lengths of
  /// opposite sides when that metric is degenerate).
  explicit FillingMap(geo::TransfinitePatch patch);

  /// Plane point of side `side` at its own parameter s in [0,1] (the loop's direction):
  /// 4 sides (s,0), (1,s), (1-s,1), (0,1-s); 3 sides (s,0), (1,s), (1-s,1-s), both
  /// forms (param()), mapped by L.
  Vec2 side_point(std::size_t side, double s) const;
  /// The patch's point at plane point p.
  Vec3 point(Vec2 p) const;
  /// Lengths on the surface per length in the plane at p: sqrt|X_x x X_y| by central
  /// differences (a degenerate point gets the smallest positive value of its cross).
  double stretch(Vec2 p) const;
  /// Records the plane point of a node at x (a boundary node placed from its curve's
  /// parameter): plane_of(x) returns it exactly.
  void remember(Vec3 x, Vec2 p) { known_[{x.x, x.y, x.z}] = p; }
  /// The plane point of x: remembered, else the closest point of the patch (the nearest
  /// of a grid of samples, then at most 40 damped Gauss-Newton steps).
  Vec2 plane_of(Vec3 x) const;
  const geo::TransfinitePatch& patch() const { return patch_; }
  /// The patch's (u, v) of a point t of the domain: t itself, but for the old 3-sided
  /// form (Geometry.OldRuledSurface), on the unit square with its side u = 0 collapsed
  /// to S0, (u, v) = (t.x, t.y / t.x) from Gmsh's triangle t.x >= t.y (its sides (s,0),
  /// (1,s), (1-s,1) of gmshEdge::reparamOnFace become those of the new form).
  Vec2 param(Vec2 t) const;
  /// Plane point of domain points (patch parameters but for param()), and back.
  Vec2 to_plane(Vec2 uv) const { return {l11_ * uv.x + l12_ * uv.y, l22_ * uv.y}; }
  Vec2 to_uv(Vec2 p) const {
    const double v = p.y / l22_;
    return {(p.x - l12_ * v) / l11_, v};
  }

 private:
  static constexpr int kGrid = 24;  // samples per direction of the initial guess
  geo::TransfinitePatch patch_;
  double l11_ = 1, l12_ = 0, l22_ = 1;  // L
  double step_ = 1e-6;                   // finite-difference step in p
  std::map<std::array<double, 3>, Vec2> known_;
  std::vector<std::pair<Vec2, Vec3>> samples_;
};

}  // namespace sm
