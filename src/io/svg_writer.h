// A picture of the mesh as SVG, for people to look at before they trust a
// mesh: triangles (optionally coloured by quality or a node field) and the
// boundary curves highlighted, in lon/lat or stereographic view.
#pragma once

#include <string>
#include <vector>

#include "base/vec.h"
#include "io/mesh_model.h"

namespace sm::io {

enum class SvgView {
  Plane,          // x, y as they are (planar meshes)
  LonLat,         // equirectangular lon/lat of points on the sphere
  Stereographic,  // Gmsh's PolarSphere (u, v) plane: the paper's Figure 4 view
};

enum class SvgColour { None, Quality, NodeValue };

struct SvgOptions {
  SvgView view = SvgView::LonLat;
  Vec3 centre{0, 0, 0};  // sphere of the mesh (for LonLat and Stereographic)
  double radius = 1;
  SvgColour colour = SvgColour::None;
  std::vector<double> node_values;  // with SvgColour::NodeValue: one per node
  double width_px = 1600;
  bool draw_triangles = true;       // false: only the boundary curves
  bool save_all = false;
};

/// The SVG document: one <polygon> per triangle (two where a triangle
/// crosses the dateline in the lon/lat view), one <polyline> per curve.
std::string svg_to_string(const MeshModel& mesh, const SvgOptions& opt);
bool save_svg(const MeshModel& mesh, const SvgOptions& opt, const std::string& path, std::string* error);

}  // namespace sm::io
