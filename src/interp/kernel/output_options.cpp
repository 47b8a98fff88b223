// The writers' settings from the script's options (see output_options.h).
#include "interp/kernel/output_options.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "interp/interpreter.h"
#include "io/node_coordinates.h"

namespace sm::interp {

namespace {

// The sphere of the model's surface geometries (every PolarSphere / Sphere of a model
// shares it in practice); nullopt for a planar model; an error when they differ.
std::optional<io::SphereFrame> model_sphere(const geo::Model& model, std::string* error) {
  std::optional<io::SphereFrame> frame;
  for (const auto& [tag, g] : model.geometries()) {
    if (!frame) {
      frame = io::SphereFrame{g.centre(), g.radius()};
    } else if (norm(g.centre() - frame->centre) > 1e-9 * frame->radius ||
               std::abs(g.radius() - frame->radius) > 1e-9 * frame->radius) {
      *error = fmt::format("the model's surface geometries lie on different spheres (geometry {} has radius {:g})",
                           tag, g.radius());
      return std::nullopt;
    }
  }
  return frame;
}

}  // namespace

std::string apply_node_coordinates(Interpreter& in, io::MeshModel& mm) {
  const double v = in.options().number("Mesh.NodeCoordinates");
  if (v != 0 && v != 1 && v != 2)
    return fmt::format("Mesh.NodeCoordinates = {:g}: use 0 (x y z), 1 (lon/lat degrees) or 2 (stereographic plane)",
                       v);
  if (v == 0) return {};
  std::string error;
  const std::optional<io::SphereFrame> sphere = model_sphere(in.kernel().model, &error);
  if (!error.empty()) return error;
  return io::convert_node_coordinates(mm, static_cast<io::NodeCoordinates>(static_cast<int>(v)), sphere);
}

std::string picture_options(Interpreter& in, io::PictureOptions& po) {
  po = {};
  const double view = in.options().number("Mesh.PictureView");
  if (view != 0 && view != 1)
    return fmt::format("Mesh.PictureView = {:g}: use 0 (lon/lat) or 1 (stereographic)", view);
  po.view = io::PictureView::Plane;
  for (const auto& [tag, g] : in.kernel().model.geometries()) {
    po.view = view == 0 ? io::PictureView::LonLat : io::PictureView::Stereographic;
    po.centre = g.centre();
    po.radius = g.radius();
    break;
  }
  const double colour = in.options().number("Mesh.PictureColour");
  if (colour != 0 && colour != 1 && colour != 2)
    return fmt::format("Mesh.PictureColour = {:g}: use 0 (plain), 1 (quality) or 2 (triangle size)", colour);
  po.colour = colour == 0 ? io::PictureColour::None : colour == 1 ? io::PictureColour::Quality : io::PictureColour::Size;
  po.save_all = in.options().number("Mesh.SaveAll") != 0;
  po.width_px = in.options().number("Mesh.PictureWidth");
  if (!(po.width_px >= 16 && po.width_px <= io::kMaxPicturePx))
    return fmt::format("Mesh.PictureWidth = {:g}: use 16 to {:g} pixels", po.width_px, io::kMaxPicturePx);
  return {};
}

}  // namespace sm::interp
