// SVG pictures of meshes (see svg_writer.h).
#include "io/svg_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geo/sphere.h"
#include "io/atomic_file.h"
#include "io/element_quality.h"

namespace sm::io {
namespace {

// Maps node positions into the view's plane (y up; flipped when drawn).
std::vector<Vec2> project(const MeshModel& m, const SvgOptions& opt) {
  std::vector<Vec2> p(m.xyz.size());
  const geo::PolarSphere sphere(opt.centre, opt.radius);
  for (std::size_t i = 0; i < m.xyz.size(); ++i) {
    switch (opt.view) {
      case SvgView::Plane: p[i] = {m.xyz[i].x, m.xyz[i].y}; break;
      case SvgView::LonLat: {
        const geo::LonLat ll = sphere.to_lonlat(m.xyz[i]);
        p[i] = {ll.lon, ll.lat};
        break;
      }
      case SvgView::Stereographic: p[i] = sphere.param(m.xyz[i]); break;
    }
  }
  return p;
}

// Colour ramp for values in [0, 1]: blue (low) to red (high) through white,
// readable in print and by most colour-blind readers.
std::string ramp(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  auto mix = [](double a, double b, double s) { return static_cast<int>(std::lround(a + (b - a) * s)); };
  int r, g, b;
  if (t < 0.5) {
    const double s = t / 0.5;
    r = mix(49, 247, s), g = mix(54, 247, s), b = mix(149, 247, s);
  } else {
    const double s = (t - 0.5) / 0.5;
    r = mix(247, 165, s), g = mix(247, 0, s), b = mix(247, 38, s);
  }
  return fmt::format("#{:02x}{:02x}{:02x}", r, g, b);
}

}  // namespace

std::string svg_to_string(const MeshModel& m, const SvgOptions& opt) {
  const std::vector<Vec2> p = project(m, opt);
  bool has_physicals = false;
  for (const EntityMesh& e : m.entities) has_physicals |= !e.physical_tags.empty();
  auto saved = [&](const EntityMesh& e) { return opt.save_all || !has_physicals || !e.physical_tags.empty(); };
  std::vector<std::size_t> order(m.entities.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const EntityMesh &ea = m.entities[a], &eb = m.entities[b];
    return ea.dim != eb.dim ? ea.dim < eb.dim : ea.tag < eb.tag;
  });

  // The picture's extent: the whole globe in lon/lat, else the used nodes.
  // Model points (a PolarSphere's centre and pole, say) are not drawn and do
  // not count: the frame is that of the drawn curves and triangles.
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const EntityMesh& e : m.entities)
    for (std::uint32_t v : e.type == ElementType::Point1 ? std::vector<std::uint32_t>{} : e.connectivity) {
      x0 = std::min(x0, p[v].x), x1 = std::max(x1, p[v].x);
      y0 = std::min(y0, p[v].y), y1 = std::max(y1, p[v].y);
    }
  if (opt.view == SvgView::LonLat) x0 = std::max(x0, -180.0), x1 = std::min(x1, 180.0);
  if (!(x1 > x0)) x0 = 0, x1 = 1;
  if (!(y1 > y0)) y0 = 0, y1 = 1;
  const double scale = opt.width_px / (x1 - x0);
  const double height = (y1 - y0) * scale;
  const double stroke = std::max(0.15, opt.width_px / 8000.0);
  auto X = [&](double x) { return (x - x0) * scale; };
  auto Y = [&](double y) { return (y1 - y) * scale; };

  double vmin = 0, vmax = 1;
  if (opt.colour == SvgColour::NodeValue && !opt.node_values.empty()) {
    const auto [lo, hi] = std::minmax_element(opt.node_values.begin(), opt.node_values.end());
    vmin = *lo, vmax = *hi > *lo ? *hi : *lo + 1;
  }

  std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.2f} {:.2f}\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#f4f1ea\"/>\n",
      opt.width_px, height, opt.width_px, height);
  auto pt = [&](Vec2 q, double shift) { return fmt::format("{:.2f},{:.2f}", X(q.x + shift), Y(q.y)); };

  if (opt.draw_triangles) {
    out += fmt::format("<g id=\"triangles\" stroke=\"#3a5a78\" stroke-width=\"{:.3f}\" stroke-linejoin=\"round\">\n",
                       stroke);
    for (std::size_t i : order) {
      const EntityMesh& e = m.entities[i];
      if (e.type != ElementType::Triangle3 || !saved(e)) continue;
      for (std::size_t k = 0; k + 2 < e.connectivity.size(); k += 3) {
        const std::uint32_t a = e.connectivity[k], b = e.connectivity[k + 1], c = e.connectivity[k + 2];
        std::string fill = "#dfe9f2";
        if (opt.colour == SvgColour::Quality) {
          fill = ramp(1 - triangle_rho(m.xyz[a], m.xyz[b], m.xyz[c]));
        } else if (opt.colour == SvgColour::NodeValue && opt.node_values.size() == m.xyz.size()) {
          const double v = (opt.node_values[a] + opt.node_values[b] + opt.node_values[c]) / 3;
          fill = ramp((v - vmin) / (vmax - vmin));
        }
        // In lon/lat a triangle across the dateline has vertices on both
        // sides: draw it shifted to either side and let the frame clip it.
        Vec2 q[3] = {p[a], p[b], p[c]};
        bool wraps = false;
        if (opt.view == SvgView::LonLat) {
          const double lo = std::min({q[0].x, q[1].x, q[2].x}), hi = std::max({q[0].x, q[1].x, q[2].x});
          if (hi - lo > 180) {
            wraps = true;
            for (Vec2& r : q)
              if (r.x < 0) r.x += 360;
          }
        }
        for (double shift : wraps ? std::initializer_list<double>{0.0, -360.0} : std::initializer_list<double>{0.0})
          out += fmt::format("<polygon points=\"{} {} {}\" fill=\"{}\"/>\n", pt(q[0], shift), pt(q[1], shift),
                             pt(q[2], shift), fill);
      }
    }
    out += "</g>\n";
  }

  // Coastlines a few pixels wide whatever the mesh's density, so they stand out.
  out += fmt::format("<g id=\"curves\" fill=\"none\" stroke=\"#b2182b\" stroke-width=\"{:.3f}\" "
                     "stroke-linejoin=\"round\">\n",
                     std::max(1.0, opt.width_px / 1000.0));
  for (std::size_t i : order) {
    const EntityMesh& e = m.entities[i];
    if (e.type != ElementType::Line2 || !saved(e)) continue;
    // Consecutive segments of a curve share nodes: emit maximal chains,
    // breaking them where the lon/lat view wraps at the dateline.
    std::string chain;
    std::uint32_t last = 0xFFFFFFFFu;
    auto flush = [&] {
      if (!chain.empty()) out += fmt::format("<polyline points=\"{}\"/>\n", chain);
      chain.clear();
    };
    for (std::size_t k = 0; k + 1 < e.connectivity.size(); k += 2) {
      const std::uint32_t a = e.connectivity[k], b = e.connectivity[k + 1];
      const bool jump = opt.view == SvgView::LonLat && std::abs(p[a].x - p[b].x) > 180;
      if (a != last || jump) {
        flush();
        if (!jump) chain = pt(p[a], 0);
      }
      if (!jump) chain += " " + pt(p[b], 0);
      last = jump ? 0xFFFFFFFFu : b;
    }
    flush();
  }
  out += "</g>\n</svg>\n";
  return out;
}

bool save_svg(const MeshModel& mesh, const SvgOptions& opt, const std::string& path, std::string* error) {
  if (std::string why = validate_mesh_model(mesh); !why.empty()) {
    *error = "cannot write '" + path + "': invalid mesh: " + why;
    return false;
  }
  AtomicFile file;
  if (!file.open(path) || !file.write(svg_to_string(mesh, opt)) || !file.commit()) {
    *error = file.error();
    return false;
  }
  return true;
}

}  // namespace sm::io
