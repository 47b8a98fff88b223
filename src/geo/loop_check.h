// Curve-loop chaining (Gmsh's SortEdgesInLoop, with located errors) and the containment test
// of a plane surface's holes in its parameter plane.
#pragma once

#include "geo/error.h"
#include "geo/surface_geometry.h"

#include <vector>

namespace sm::geo {

class Model;
struct ModelCurveLoop;

/// A signed curve of a loop with its oriented end vertices.
struct LoopEdge {
  int curve = 0;   // signed tag
  int from = 0, to = 0;
};

/// Gmsh's order: start with the first curve, then repeatedly take the first remaining curve
/// (in written order) that starts where the chain ends; when a chain closes and curves
/// remain, a new chain ("subloop") starts with the first remaining one. Errors name the
/// curve where the chain breaks (and a curve that would fit with the other sign).
GeoResult<std::vector<int>> chain_loop(int loop_tag, const std::vector<LoopEdge>& edges);

/// A loop of discrete curves as Gmsh 4.8.4 takes it (Geo/Geo.cpp's SortEdgesInLoop leaves
/// such a loop unsorted, and its mesher uses the curves' edges whatever their signs): each
/// chain continues with the first remaining curve, in written order, that starts or ends
/// where the chain ends, reversed when it ends there. Returns the signed tags in chained
/// order; the errors are chain_loop's.
GeoResult<std::vector<int>> chain_loop_reorienting(int loop_tag, const std::vector<LoopEdge>& edges);

/// A loop sampled densely enough for containment tests: (u,v) when drawn on a geometry,
/// else points in space.
struct LoopPolygon {
  std::vector<Vec3> xyz;
  std::vector<Vec2> uv;
};
LoopPolygon sample_loop(const Model& m, const ModelCurveLoop& loop, const SurfaceGeometry* g);
/// `count` points spread evenly over the loop's curves (by curve, then along it): the probe
/// points of a hole, without sampling all of a 35k-point coastline.
LoopPolygon probe_loop(const Model& m, const ModelCurveLoop& loop, const SurfaceGeometry* g, int count);

/// Mean plane of a polygon in space (Newell's normal) and the projection onto it.
struct PlaneFrame {
  Vec3 origin, e1{1, 0, 0}, e2{0, 1, 0};
  std::vector<Vec2> project(const std::vector<Vec3>& pts) const;
};
PlaneFrame plane_frame(const std::vector<Vec3>& pts);

/// Even-odd point-in-polygon test against a fixed polygon, with its edges sorted into
/// horizontal bands so that a query visits about sqrt(n) edges; each edge's ray crossing is
/// exact (exact/ring.h). A point on the boundary counts as outside.
class PolygonIndex {
 public:
  explicit PolygonIndex(std::vector<Vec2> polygon);
  bool contains(Vec2 p) const;

 private:
  int band_of(double y) const;
  std::vector<Vec2> poly_;
  double ylo_ = 0, yhi_ = 0, h_ = 0;
  int bands_ = 1;
  std::vector<std::vector<std::size_t>> edges_;
};

/// Whether polygon `inner` lies inside the indexed polygon, tested on up to 16 of its
/// points spread along it.
bool polygon_inside(const std::vector<Vec2>& inner, const PolygonIndex& outer);

}  // namespace sm::geo
