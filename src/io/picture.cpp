// The scene of a mesh picture (see picture.h): projection, frame, colours.
#include "io/picture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "exact/triangle_rho.h"
#include "geo/sphere.h"

namespace sm::io {
namespace {

// Maps node positions into the view's plane (y up; flipped into pixels later).
std::vector<Vec2> project(const MeshModel& m, const PictureOptions& opt) {
  std::vector<Vec2> p(m.xyz.size());
  const geo::PolarSphere sphere(opt.centre, opt.radius);
  for (std::size_t i = 0; i < m.xyz.size(); ++i) {
    switch (opt.view) {
      case PictureView::Plane: p[i] = {m.xyz[i].x, m.xyz[i].y}; break;
      case PictureView::LonLat: {
        const geo::LonLat ll = sphere.to_lonlat(m.xyz[i]);
        p[i] = {ll.lon, ll.lat};
        break;
      }
      case PictureView::Stereographic: p[i] = sphere.param(m.xyz[i]); break;
    }
  }
  return p;
}

// Colour ramp for values in [0, 1]: blue (low) to red (high) through white,
// readable in print and by most colour-blind readers.
Rgb ramp(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  auto mix = [](double a, double b, double s) { return static_cast<std::uint8_t>(std::lround(a + (b - a) * s)); };
  if (t < 0.5) {
    const double s = t / 0.5;
    return {mix(49, 247, s), mix(54, 247, s), mix(149, 247, s)};
  }
  const double s = (t - 0.5) / 0.5;
  return {mix(247, 165, s), mix(247, 0, s), mix(247, 38, s)};
}

}  // namespace

Scene build_scene(const MeshModel& m, const PictureOptions& opt) {
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

  // The picture's extent: the used nodes, at most the whole longitude range in
  // lon/lat. Model points (a PolarSphere's centre and pole, say) are not drawn
  // and do not count: the frame is that of the drawn curves and triangles.
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const EntityMesh& e : m.entities) {
    if (e.type == ElementType::Point1) continue;
    for (std::uint32_t v : e.connectivity) {
      x0 = std::min(x0, p[v].x), x1 = std::max(x1, p[v].x);
      y0 = std::min(y0, p[v].y), y1 = std::max(y1, p[v].y);
    }
  }
  if (opt.view == PictureView::LonLat) x0 = std::max(x0, -180.0), x1 = std::min(x1, 180.0);
  if (!(x1 > x0)) x0 = 0, x1 = 1;
  if (!(y1 > y0)) y0 = 0, y1 = 1;
  // A margin as wide as the coastlines, so that curves on the frame are drawn whole.
  const double curve_width = std::max(1.0, opt.width_px / 1000.0);
  const double margin = curve_width;
  double scale = std::max(1.0, opt.width_px - 2 * margin) / (x1 - x0);
  if ((y1 - y0) * scale + 2 * margin > kMaxPicturePx) scale = (kMaxPicturePx - 2 * margin) / (y1 - y0);

  Scene sc;
  sc.width = (x1 - x0) * scale + 2 * margin;
  sc.height = (y1 - y0) * scale + 2 * margin;
  sc.draw_triangles = opt.draw_triangles;
  sc.edge_width = std::max(0.15, opt.width_px / 8000.0);
  // Coastlines a few pixels wide whatever the mesh's density, so they stand out.
  sc.curve_width = curve_width;
  auto px = [&](Vec2 q, double shift) { return Vec2{margin + (q.x + shift - x0) * scale, margin + (y1 - q.y) * scale}; };

  double vmin = 0, vmax = 1;
  if (opt.colour == PictureColour::NodeValue && !opt.node_values.empty()) {
    const auto [lo, hi] = std::minmax_element(opt.node_values.begin(), opt.node_values.end());
    vmin = *lo, vmax = *hi > *lo ? *hi : *lo + 1;
  }

  auto mean_edge = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return (norm(m.xyz[b] - m.xyz[a]) + norm(m.xyz[c] - m.xyz[b]) + norm(m.xyz[a] - m.xyz[c])) / 3;
  };
  double log_lo = 0, log_span = 1;   // PictureColour::Size: log of the edge length range
  if (opt.colour == PictureColour::Size) {
    double lo = std::numeric_limits<double>::max(), hi = 0;
    for (const EntityMesh& e : m.entities) {
      if (e.type != ElementType::Triangle3 || !saved(e)) continue;
      for (std::size_t k = 0; k + 2 < e.connectivity.size(); k += 3) {
        const double l = mean_edge(e.connectivity[k], e.connectivity[k + 1], e.connectivity[k + 2]);
        if (l > 0) lo = std::min(lo, l), hi = std::max(hi, l);
      }
    }
    if (hi > 0) log_lo = std::log(lo), log_span = hi > lo ? std::log(hi / lo) : 1;
  }

  if (opt.draw_triangles) {
    for (std::size_t i : order) {
      const EntityMesh& e = m.entities[i];
      if (e.type != ElementType::Triangle3 || !saved(e)) continue;
      for (std::size_t k = 0; k + 2 < e.connectivity.size(); k += 3) {
        const std::uint32_t a = e.connectivity[k], b = e.connectivity[k + 1], c = e.connectivity[k + 2];
        Rgb fill{0xdf, 0xe9, 0xf2};
        if (opt.colour == PictureColour::Quality) {
          fill = ramp(1 - rho(m.xyz[a], m.xyz[b], m.xyz[c]));
        } else if (opt.colour == PictureColour::NodeValue && opt.node_values.size() == m.xyz.size()) {
          const double v = (opt.node_values[a] + opt.node_values[b] + opt.node_values[c]) / 3;
          fill = ramp((v - vmin) / (vmax - vmin));
        } else if (opt.colour == PictureColour::Size) {
          const double l = mean_edge(a, b, c);
          fill = ramp(l > 0 ? (std::log(l) - log_lo) / log_span : 0.0);
        }
        // In lon/lat a triangle across the dateline has vertices on both
        // sides: draw it shifted to either side and let the frame clip it.
        Vec2 q[3] = {p[a], p[b], p[c]};
        bool wraps = false;
        if (opt.view == PictureView::LonLat) {
          const double lo = std::min({q[0].x, q[1].x, q[2].x}), hi = std::max({q[0].x, q[1].x, q[2].x});
          if (hi - lo > 180) {
            wraps = true;
            for (Vec2& r : q)
              if (r.x < 0) r.x += 360;
          }
        }
        for (int copy = 0; copy < (wraps ? 2 : 1); ++copy) {
          const double shift = copy == 0 ? 0.0 : -360.0;
          sc.triangles.push_back({{px(q[0], shift), px(q[1], shift), px(q[2], shift)}, fill});
        }
      }
    }
  }

  if (!sc.triangles.empty()) {
    double sum = 0;
    for (const Scene::Triangle& t : sc.triangles)
      sum += norm(t.p[1] - t.p[0]) + norm(t.p[2] - t.p[1]) + norm(t.p[0] - t.p[2]);
    if (sum / (3.0 * static_cast<double>(sc.triangles.size())) < kMinEdgePx) sc.edge_width = 0;
  }

  for (std::size_t i : order) {
    const EntityMesh& e = m.entities[i];
    if (e.type != ElementType::Line2 || !saved(e)) continue;
    // Consecutive segments of a curve share nodes: emit maximal chains,
    // breaking them where the lon/lat view wraps at the dateline.
    std::vector<Vec2> chain;
    std::uint32_t last = 0xFFFFFFFFu;
    auto flush = [&] {
      if (!chain.empty()) sc.polylines.push_back(std::move(chain));
      chain.clear();
    };
    for (std::size_t k = 0; k + 1 < e.connectivity.size(); k += 2) {
      const std::uint32_t a = e.connectivity[k], b = e.connectivity[k + 1];
      const bool jump = opt.view == PictureView::LonLat && std::abs(p[a].x - p[b].x) > 180;
      if (a != last || jump) {
        flush();
        if (!jump) chain.push_back(px(p[a], 0));
      }
      if (!jump) chain.push_back(px(p[b], 0));
      last = jump ? 0xFFFFFFFFu : b;
    }
    flush();
  }
  return sc;
}

}  // namespace sm::io
