// SVG pictures of meshes (see svg_writer.h): the shared Scene written as XML.
#include "io/svg_writer.h"

#include <fmt/format.h>

#include "base/output_file.h"

namespace sm::io {
namespace {

std::string hex(Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

std::string pt(Vec2 q) { return fmt::format("{:.2f},{:.2f}", q.x, q.y); }

}  // namespace

std::string svg_to_string(const Scene& sc) {
  std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.2f} {:.2f}\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"{}\"/>\n",
      sc.width, sc.height, sc.width, sc.height, hex(sc.background));
  if (sc.draw_triangles) {
    if (sc.edge_width > 0)
      out += fmt::format("<g id=\"triangles\" stroke=\"{}\" stroke-width=\"{:.3f}\" stroke-linejoin=\"round\">\n",
                         hex(sc.edge), sc.edge_width);
    else
      out += "<g id=\"triangles\" stroke=\"none\">\n";
    for (const Scene::Triangle& t : sc.triangles)
      out += fmt::format("<polygon points=\"{} {} {}\" fill=\"{}\"/>\n", pt(t.p[0]), pt(t.p[1]), pt(t.p[2]),
                         hex(t.fill));
    out += "</g>\n";
  }
  out += fmt::format("<g id=\"curves\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.3f}\" "
                     "stroke-linejoin=\"round\">\n",
                     hex(sc.curve), sc.curve_width);
  for (const std::vector<Vec2>& line : sc.polylines) {
    out += "<polyline points=\"";
    for (std::size_t k = 0; k < line.size(); ++k) {
      if (k) out += ' ';
      out += pt(line[k]);
    }
    out += "\"/>\n";
  }
  out += "</g>\n</svg>\n";
  return out;
}

std::string svg_to_string(const MeshModel& mesh, const PictureOptions& opt) {
  return svg_to_string(build_scene(mesh, opt));
}

bool save_svg(const MeshModel& mesh, const PictureOptions& opt, const std::string& path, std::string* error) {
  if (std::string why = validate_mesh_model(mesh); !why.empty()) {
    *error = "invalid mesh: " + why;
    return false;
  }
  base::OutputFile file;
  if (!file.open(path) || !file.write(svg_to_string(mesh, opt)) || !file.commit()) {
    *error = file.error();
    return false;
  }
  return true;
}

}  // namespace sm::io
