// SVG pictures of meshes (see svg_writer.h): the shared Scene written as XML.
#include "io/svg_writer.h"

#include <fmt/format.h>

#include "base/output_file.h"

namespace sm::io {
namespace {

std::string hex(Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

std::string pt(Vec2 q) { return fmt::format("{:.2f},{:.2f}", q.x, q.y); }

// Text as XML character data or an attribute value.
std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string points(const std::vector<Vec2>& line) {
  std::string out;
  for (std::size_t k = 0; k < line.size(); ++k) {
    if (k) out += ' ';
    out += pt(line[k]);
  }
  return out;
}

void add_texts(std::string& out, const std::vector<Scene::Text>& texts, Rgb halo) {
  for (const Scene::Text& t : texts) {
    const char* anchor = t.anchor == Scene::Anchor::Start    ? "start"
                         : t.anchor == Scene::Anchor::Middle ? "middle"
                                                             : "end";
    out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{:.2f}\" text-anchor=\"{}\" fill=\"{}\"", t.at.x,
                       t.at.y, t.size, anchor, hex(t.colour));
    if (t.halo)
      out += fmt::format(" stroke=\"{}\" stroke-width=\"{:.2f}\" paint-order=\"stroke\"", hex(halo), t.size / 4);
    out += fmt::format(">{}</text>\n", escaped(t.text));
  }
}

}  // namespace

std::string svg_to_string(const Scene& sc) {
  std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.2f} {:.2f}\">\n"
      "<defs><clipPath id=\"frame\"><rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\"/>"
      "</clipPath></defs>\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"{}\"/>\n"
      "<g id=\"map\" clip-path=\"url(#frame)\">\n",
      sc.width, sc.height, sc.width, sc.height, sc.map.lo.x - sc.curve_width, sc.map.lo.y - sc.curve_width,
      sc.map.hi.x - sc.map.lo.x + 2 * sc.curve_width, sc.map.hi.y - sc.map.lo.y + 2 * sc.curve_width,
      hex(sc.background));
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
  if (!sc.graticule.empty()) {
    // Under the dashes a faint solid line of the background colour, so that the graticule
    // reads on a dense dark mesh as on land.
    out += fmt::format("<g id=\"graticule-halo\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.3f}\" "
                       "stroke-opacity=\"0.6\">\n",
                       hex(sc.background), 3 * sc.graticule_width);
    for (const Scene::GridLine& g : sc.graticule) out += fmt::format("<polyline points=\"{}\"/>\n", points(g.p));
    out += "</g>\n";
    out += fmt::format("<g id=\"graticule\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.3f}\" "
                       "stroke-dasharray=\"{:.2f} {:.2f}\">\n",
                       hex(sc.graticule_colour), sc.graticule_width, 4 * sc.graticule_width, 3 * sc.graticule_width);
    for (const Scene::GridLine& g : sc.graticule)
      out += fmt::format("<polyline class=\"{}\" points=\"{}\"/>\n", g.meridian ? "meridian" : "parallel", points(g.p));
    out += "</g>\n";
  }
  out += fmt::format("<g id=\"curves\" fill=\"none\" stroke-width=\"{:.3f}\" stroke-linejoin=\"round\" "
                     "stroke-linecap=\"round\">\n",
                     sc.curve_width);
  for (const Scene::Curve& c : sc.polylines)
    out += fmt::format("<polyline stroke=\"{}\" points=\"{}\"/>\n", hex(sc.curve_styles[c.style].colour), points(c.p));
  out += "</g>\n";
  if (!sc.points.empty()) {
    out += "<g id=\"points\">\n";
    for (const Scene::Circle& c : sc.points)
      out += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"{}\"/>\n", c.centre.x, c.centre.y,
                         c.radius, hex(c.colour));
    out += "</g>\n";
  }
  if (!sc.marks.empty()) {
    out += "<g id=\"marks\" fill=\"none\">\n";
    for (const Scene::Circle& c : sc.marks)
      out += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" stroke=\"{}\" stroke-width=\"{:.2f}\"/>\n",
                         c.centre.x, c.centre.y, c.radius, hex(c.colour), c.width);
    out += "</g>\n";
  }
  out += "</g>\n";
  if (!sc.map_labels.empty()) {
    out += "<g id=\"graticule-labels\" font-family=\"sans-serif\">\n";
    add_texts(out, sc.map_labels, sc.background);
    out += "</g>\n";
  }
  if (!sc.texts.empty() || !sc.boxes.empty()) {
    out += "<g id=\"legend\" font-family=\"sans-serif\">\n";
    for (const Scene::Box& b : sc.boxes)
      out += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"/>\n", b.lo.x,
                         b.lo.y, b.hi.x - b.lo.x, b.hi.y - b.lo.y, hex(b.fill));
    for (const Scene::Line& l : sc.lines)
      out += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{:.2f}\" points=\"{}\"/>\n",
                         hex(l.colour), l.width, points(l.p));
    for (const Scene::Circle& c : sc.circles)   // width 0: a filled dot
      out += c.width > 0 ? fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"none\" stroke=\"{}\" "
                                       "stroke-width=\"{:.2f}\"/>\n",
                                       c.centre.x, c.centre.y, c.radius, hex(c.colour), c.width)
                         : fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"{}\"/>\n", c.centre.x,
                                       c.centre.y, c.radius, hex(c.colour));
    add_texts(out, sc.texts, sc.background);
    out += "</g>\n";
  }
  out += "</svg>\n";
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
