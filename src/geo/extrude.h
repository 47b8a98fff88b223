// Gmsh's Extrude for the built-in kernel (Geo/Geo.cpp's ExtrudePoint / ExtrudeCurve /
// ExtrudeSurface, read for their meaning): what an extrusion is, where it moves a point,
// and what the model remembers of each extruded entity for the structured (Layers) mesh.
#pragma once

#include <vector>

#include "base/vec.h"

namespace sm::geo {

enum class ExtrudeKind { Translate, Rotate, Twist };

/// `Layers{n}` (one layer of n elements up to height 1) or `Layers{{n1,..},{h1,..}}` (layer
/// i: n_i elements up to the cumulative height h_i, a fraction of the extrusion).
struct ExtrudeLayers {
  std::vector<int> elements;
  std::vector<double> heights;
  /// The fractions of the extrusion where the nodes sit: 0, then each element's top
  /// (Gmsh's ExtrudeParams::u).
  std::vector<double> fractions() const;
};

struct ExtrudeSpec {
  ExtrudeKind kind = ExtrudeKind::Translate;
  Vec3 translation;     // Translate, Twist
  Vec3 axis, point;     // Rotate, Twist
  double angle = 0;     // Rotate, Twist
  bool layered = false;  // Layers given (n > 0): a structured mesh
  ExtrudeLayers layers;
  bool recombine = false;  // Recombine: quadrangles, else each cell split in two triangles
  int spline_points = 5;   // Geometry.ExtrudeSplinePoints (twist)
  bool return_lateral = true;  // Geometry.ExtrudeReturnLateralEntities
};

/// Where the extrusion takes p at fraction t in [0, 1] (Gmsh's ExtrudeParams::Extrude:
/// the rotation by t * angle about the axis through `point`, then t * translation).
Vec3 extrude_point(const ExtrudeSpec& s, Vec3 p, double t);

/// What the model remembers of an entity made by Extrude. `body`: the entity swept from
/// `source` (a curve from a point, a surface from a curve); else the top copy of `source`
/// (signed as Gmsh keeps it). `begin_curve` / `end_curve` (surfaces swept from a curve):
/// the curves swept from the source curve's end points (0 where the point is on the axis),
/// `top`: the copy of the source curve.
struct Extrusion {
  ExtrudeSpec spec;
  int source = 0;
  bool body = true;
  int begin_curve = 0, end_curve = 0, top = 0;
};

}  // namespace sm::geo
