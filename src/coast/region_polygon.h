// Region clipping of shorelines to a polygon on the sphere whose edges are great-circle
// arcs: the open boundary a regional model draws from one headland to another. Clipping is
// done in the gnomonic projection about the polygon's centre, where every great circle is a
// straight line, so the polygon is an ordinary planar polygon there and every side decision
// is an exact orient2d. The cut coasts are closed along the polygon as region.cpp closes
// them along a box; the closing pieces are the open boundaries.
#pragma once

#include <cstddef>
#include <vector>

#include "base/vec.h"
#include "coast/coastline.h"
#include "coast/region.h"

namespace sm::coast {

/// Largest angle (degrees) between a vertex and the polygon's centre: the gnomonic
/// projection stretches lengths by up to 1 / cos^2 of it (4x at 60 degrees).
inline constexpr double kRegionPolygonMaxRadiusDeg = 60.0;
/// Most vertices a polygon may have (its simplicity check compares every pair of edges).
inline constexpr std::size_t kRegionPolygonMaxVertices = 4096;

/// A simple polygon on the sphere, great-circle edges, counter-clockwise (its inside on
/// the left of each edge, seen from above the sphere). Edges are numbered as given: edge
/// k runs from the k-th given vertex to the next.
class RegionPolygon {
 public:
  /// Errors (option "Region"): fewer than 3 vertices, a latitude outside [-90, 90], two
  /// equal consecutive vertices, a vertex more than kRegionPolygonMaxRadiusDeg from the
  /// centre, edges that cross or touch (self-crossing), no area, a pole inside.
  static Result<RegionPolygon> make(const std::vector<geo::LonLat>& vertices);

  std::size_t size() const { return gn_.size(); }
  /// Vertex i of the counter-clockwise order, in the gnomonic plane and in lon/lat.
  Vec2 plane(std::size_t i) const { return gn_[i]; }
  geo::LonLat vertex(std::size_t i) const { return ll_[i]; }
  /// The given edge number (0-based) of the counter-clockwise edge i -> i + 1.
  std::size_t given_edge(std::size_t i) const { return reversed_ ? (2 * size() - 2 - i) % size() : i; }

  /// Gnomonic coordinates of p; false when p lies more than 85 degrees from the centre
  /// (no point of the polygon is within 25 degrees of it).
  bool project(geo::LonLat p, Vec2& out) const;
  /// The point of the sphere at gnomonic (x, y), its longitude within 180 degrees of near_lon.
  geo::LonLat unproject(Vec2 xy, double near_lon) const;
  /// The point at angle fraction f (0..1) of the great-circle arc a -> b, longitude
  /// within 180 degrees of a's.
  static geo::LonLat along_arc(geo::LonLat a, geo::LonLat b, double f);
  /// Angle between two points, degrees.
  static double arc_deg(geo::LonLat a, geo::LonLat b);

  /// Strictly inside (a point on an edge is outside).
  bool contains(geo::LonLat p) const;
  /// A lon/lat box holding the polygon, edges' bulges towards the poles included (for
  /// reading only the shoreline data that may lie inside).
  LonLatBox bounding_box() const;
  /// Given edge numbers (0-based, ascending, each once) along which two consecutive points
  /// of pts both lie (within 1e-9 radians of the edge's great circle, between its ends).
  std::vector<std::size_t> edges_along(const std::vector<geo::LonLat>& pts) const;

 private:
  std::vector<Vec2> gn_;             // counter-clockwise, gnomonic
  std::vector<geo::LonLat> ll_;      // the same vertices in lon/lat
  Vec3 c_, e1_, e2_;                 // centre, east and north at the centre
  Vec2 lo_, hi_;                     // bounding box of gn_
  bool reversed_ = false;            // the given order was clockwise
};

/// `rings` must be cleaned and oriented land-on-the-left (orient_rings). The same result
/// as clip_to_region gives for a box: rings wholly inside, and loops of coast pieces
/// closed by open-boundary pieces that follow the polygon's edges (points every
/// boundary_step_deg of arc, graded towards each vertex as towards a box corner).
/// Errors: an open polyline ending inside the polygon, a shoreline segment reaching the
/// polygon from more than 85 degrees away, inconsistent orientations, the polygon wholly
/// on land.
Result<RegionResult> clip_to_polygon(const std::vector<Ring>& rings, const RegionPolygon& poly,
                                     const RegionOptions& opt = {});

}  // namespace sm::coast
