// What a picture of a mesh shows, independent of the file format: the view (plane, lon/lat,
// stereographic), the frame, filled triangles and highlighted boundary curves in pixel
// coordinates. svg_writer and png_writer are two back ends of one Scene.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "base/vec.h"
#include "io/mesh_model.h"

namespace sm::io {

enum class PictureView {
  Plane,          // x, y as they are (planar meshes)
  LonLat,         // equirectangular lon/lat of points on the sphere
  Stereographic,  // Gmsh's PolarSphere (u, v) plane: the paper's Figure 4 view
};

/// Triangle fills: plain; quality 1 - rho (blue good, red bad); a node field; or size,
/// the triangle's mean edge length in 3D on a log scale from the smallest (blue) to the
/// largest (red) triangle drawn, which shows a multiscale mesh's grading.
enum class PictureColour { None, Quality, NodeValue, Size };

struct PictureOptions {
  PictureView view = PictureView::LonLat;
  Vec3 centre{0, 0, 0};  // sphere of the mesh (for LonLat and Stereographic)
  double radius = 1;
  PictureColour colour = PictureColour::None;
  std::vector<double> node_values;  // with PictureColour::NodeValue: one per node
  double width_px = 1600;
  bool draw_triangles = true;       // false: only the boundary curves
  bool save_all = false;
};

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(Rgb a, Rgb b) = default;
};

/// The drawing, in pixels with y down, in drawing order (triangles by entity (dim, tag),
/// then curves): what both back ends render.
struct Scene {
  struct Triangle {
    std::array<Vec2, 3> p;
    Rgb fill;
  };
  double width = 0, height = 0;         // pixels (not rounded)
  Rgb background{0xf4, 0xf1, 0xea};
  bool draw_triangles = true;
  Rgb edge{0x3a, 0x5a, 0x78};           // triangle edges
  double edge_width = 0.2;              // 0: edges not drawn (triangles too small to see them)
  std::vector<Triangle> triangles;      // a triangle across the dateline appears twice
  Rgb curve{0xb2, 0x18, 0x2b};          // boundary curves (coastlines)
  double curve_width = 1;
  std::vector<std::vector<Vec2>> polylines;
};

/// Pictures are at most this many pixels in either direction (cairo's image limit is
/// 32767): a very tall frame is scaled down to fit.
inline constexpr double kMaxPicturePx = 16384;

/// The scene of `mesh` as `opt` asks: entities chosen as the MSH writers choose them (those
/// in physical groups when there are any, unless save_all), the frame of the drawn
/// triangles and curves (the whole longitude range at most in lon/lat), triangles across
/// the dateline drawn on both sides, curves split where they wrap. Triangle edges are drawn
/// only when the triangles' mean edge is at least kMinEdgePx pixels (a dense mesh drawn
/// small would otherwise be all edge colour); the fills still show sizes or quality.
inline constexpr double kMinEdgePx = 3;
Scene build_scene(const MeshModel& mesh, const PictureOptions& opt);

}  // namespace sm::io
