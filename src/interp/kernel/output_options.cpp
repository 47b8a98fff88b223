// The writers' settings from the script's options (see output_options.h).
#include "interp/kernel/output_options.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <set>
#include <string_view>

#include "interp/interpreter.h"
#include "interp/kernel/node_data_export.h"
#include "interp/kernel/quality_floor_option.h"
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

// The legend's names of the size criteria found at the nodes: 0 the coast's channel width,
// -1 none, else the field's id and kind, after the script's variables naming it (those
// ending in "Field", as stdlib/ocean_fields.geo's ShoreField, WaveField, HessianField).
std::vector<std::pair<double, std::string>> criterion_names(Interpreter& in, const std::vector<double>& values) {
  std::set<double> seen(values.begin(), values.end());
  std::vector<std::pair<double, std::string>> names;
  const field::FieldSet& fields = in.kernel().fields;
  for (double v : seen) {
    if (v == 0) {
      names.push_back({v, "channel width (Mesh.ElementsAcrossChannels)"});
      continue;
    }
    if (v < 0) {
      names.push_back({v, "no size criterion"});
      continue;
    }
    const int id = static_cast<int>(v);
    std::string vars;
    for (const auto& [name, sym] : in.symbols().nums()) {
      constexpr std::string_view kSuffix = "Field";
      if (sym.is_list || sym.values.size() != 1 || sym.values[0] != v || name.size() <= kSuffix.size() ||
          name.compare(name.size() - kSuffix.size(), kSuffix.size(), kSuffix) != 0)
        continue;
      vars += (vars.empty() ? "" : "/") + name;
    }
    const std::string kind = fields.contains(id) ? fields.options(id).kind().name : "?";
    names.push_back({v, vars.empty() ? fmt::format("Field[{}] ({})", id, kind)
                                     : fmt::format("{}: Field[{}] ({})", vars, id, kind)});
  }
  return names;
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

std::string picture_options(Interpreter& in, const io::MeshModel& mm, io::PictureOptions& po) {
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
  if (colour != 0 && colour != 1 && colour != 2 && colour != 3 && colour != 4)
    return fmt::format(
        "Mesh.PictureColour = {:g}: use 0 (plain), 1 (quality), 2 (triangle size), 3 (size criterion) or 4 (depth)",
        colour);
  po.colour = colour == 0   ? io::PictureColour::None
              : colour == 1 ? io::PictureColour::Quality
                            : io::PictureColour::Size;
  if (colour == 3 || colour == 4) {
    std::vector<io::NodeData> data;
    if (std::string why = node_data_named(in, mm, {colour == 3 ? "criterion" : "depth"}, data); !why.empty())
      return fmt::format("Mesh.PictureColour = {:g}: {}", colour,
                         why.rfind("Mesh.NodeData: ", 0) == 0 ? why.substr(15) : why);
    po.node_values = std::move(data.front().values);
    if (colour == 3) {
      po.colour = io::PictureColour::Category;
      po.category_names = criterion_names(in, po.node_values);
    } else {
      po.colour = io::PictureColour::NodeValue;
      po.node_values_title = "depth (m)";
    }
  }
  const interp::LonLatBox& box = in.options().box("Mesh.PictureBox");
  if (box != interp::LonLatBox{0, 0, 0, 0}) {
    io::PictureBox b;
    if (OptionRefusal r = check_picture_box(box, &b); !r.empty()) return r.message;
    po.box = b;
  }
  po.worst = static_cast<int>(in.options().number("Mesh.PictureWorst"));
  // The floor the mesher lifted triangles to; with it off (0, and on a flat model by
  // default), the default 0.3 still flags the triangles a model may choke on.
  if (const double floor = quality_floor_in_effect(in); floor > 0) po.quality_floor = floor;
  po.draw_points = in.options().number("Mesh.PicturePoints") != 0;
  po.colour_min = in.options().number("Mesh.PictureColourMin");
  po.colour_max = in.options().number("Mesh.PictureColourMax");
  if ((po.colour_min != 0 || po.colour_max != 0) && !(po.colour_max > po.colour_min))
    return fmt::format("Mesh.PictureColourMin = {:g} must be below Mesh.PictureColourMax = {:g}", po.colour_min,
                       po.colour_max);
  if (colour == 2 && po.colour_max > po.colour_min && !(po.colour_min > 0))
    return fmt::format("Mesh.PictureColourMin = {:g}: a size scale is logarithmic, give a size above 0 km",
                       po.colour_min);
  po.save_all = in.options().number("Mesh.SaveAll") != 0;
  po.width_px = in.options().number("Mesh.PictureWidth");
  if (!(po.width_px >= 16 && po.width_px <= io::kMaxPicturePx))
    return fmt::format("Mesh.PictureWidth = {:g}: use 16 to {:g} pixels", po.width_px, io::kMaxPicturePx);
  return {};
}

}  // namespace sm::interp
