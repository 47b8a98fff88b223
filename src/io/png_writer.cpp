// PNG pictures of meshes (see png_writer.h): the shared Scene drawn with cairo.
#include "io/png_writer.h"

#include <cairo.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "base/output_file.h"

namespace sm::io {
namespace {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

void set_colour(cairo_t* cr, Rgb c) { cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0); }

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void polyline(cairo_t* cr, const std::vector<Vec2>& p) {
  if (p.empty()) return;
  cairo_move_to(cr, p[0].x, p[0].y);
  for (std::size_t k = 1; k < p.size(); ++k) cairo_line_to(cr, p[k].x, p[k].y);
  cairo_stroke(cr);
}

// A circle outlined `width` wide, or a filled dot when the width is 0.
void circle(cairo_t* cr, const Scene::Circle& c) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, c.centre.x, c.centre.y, c.radius, 0, 6.283185307179586);
  set_colour(cr, c.colour);
  if (c.width > 0) {
    cairo_set_line_width(cr, c.width);
    cairo_stroke(cr);
  } else {
    cairo_fill(cr);
  }
}

// A label at its anchor, with a halo in `halo` when asked (labels on the map).
void text(cairo_t* cr, const Scene::Text& t, Rgb halo) {
  cairo_set_font_size(cr, t.size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, t.text.c_str(), &ext);
  double x = t.at.x;
  if (t.anchor == Scene::Anchor::Middle) x -= ext.x_advance / 2;
  if (t.anchor == Scene::Anchor::End) x -= ext.x_advance;
  cairo_move_to(cr, x, t.at.y);
  cairo_text_path(cr, t.text.c_str());
  if (t.halo) {
    set_colour(cr, halo);
    cairo_set_line_width(cr, t.size / 4);
    cairo_stroke_preserve(cr);
  }
  set_colour(cr, t.colour);
  cairo_fill(cr);
}

}  // namespace

std::string png_to_string(const Scene& sc, std::string* error) {
  const int w = std::max(1, static_cast<int>(std::lround(sc.width)));
  const int h = std::max(1, static_cast<int>(std::lround(sc.height)));
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    *error = std::string("cannot draw the picture: ") + cairo_status_to_string(cairo_surface_status(surface.get()));
    return {};
  }
  std::unique_ptr<cairo_t, ContextDeleter> owner(cairo_create(surface.get()));
  cairo_t* cr = owner.get();
  set_colour(cr, sc.background);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  // The map, clipped to its frame (and the coastlines' margin around it), as the SVG's clipPath.
  cairo_save(cr);
  cairo_rectangle(cr, sc.map.lo.x - sc.curve_width, sc.map.lo.y - sc.curve_width,
                  sc.map.hi.x - sc.map.lo.x + 2 * sc.curve_width, sc.map.hi.y - sc.map.lo.y + 2 * sc.curve_width);
  cairo_clip(cr);
  if (sc.draw_triangles) {
    // Each triangle is filled then outlined, in scene order, as the SVG back end
    // draws its polygons, so both pictures look alike.
    cairo_set_line_width(cr, sc.edge_width > 0 ? sc.edge_width : 0.5);
    for (const Scene::Triangle& t : sc.triangles) {
      cairo_move_to(cr, t.p[0].x, t.p[0].y);
      cairo_line_to(cr, t.p[1].x, t.p[1].y);
      cairo_line_to(cr, t.p[2].x, t.p[2].y);
      cairo_close_path(cr);
      set_colour(cr, t.fill);
      if (sc.edge_width > 0) {
        cairo_fill_preserve(cr);
        set_colour(cr, sc.edge);
        cairo_stroke(cr);
      } else {
        // Tiny triangles: outlined in their own colour, so that antialiased neighbours do
        // not let the background show through their shared edges.
        cairo_fill_preserve(cr);
        cairo_stroke(cr);
      }
    }
  }
  if (!sc.graticule.empty()) {
    // A faint solid line of the background colour under the dashes (as the SVG's halo).
    cairo_set_line_width(cr, 3 * sc.graticule_width);
    cairo_set_source_rgba(cr, sc.background.r / 255.0, sc.background.g / 255.0, sc.background.b / 255.0, 0.6);
    for (const Scene::GridLine& g : sc.graticule) polyline(cr, g.p);
    cairo_set_line_width(cr, sc.graticule_width);
    const double dash[2] = {4 * sc.graticule_width, 3 * sc.graticule_width};
    cairo_set_dash(cr, dash, 2, 0);
    set_colour(cr, sc.graticule_colour);
    for (const Scene::GridLine& g : sc.graticule) polyline(cr, g.p);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_set_line_width(cr, sc.curve_width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const Scene::Curve& c : sc.polylines) {
    set_colour(cr, sc.curve_styles[c.style].colour);
    polyline(cr, c.p);
  }
  for (const Scene::Circle& c : sc.points) circle(cr, c);
  for (const Scene::Circle& c : sc.marks) circle(cr, c);
  cairo_restore(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  for (const Scene::Text& t : sc.map_labels) text(cr, t, sc.background);
  for (const Scene::Box& b : sc.boxes) {
    cairo_rectangle(cr, b.lo.x, b.lo.y, b.hi.x - b.lo.x, b.hi.y - b.lo.y);
    set_colour(cr, b.fill);
    cairo_fill(cr);
  }
  for (const Scene::Line& l : sc.lines) {
    cairo_set_line_width(cr, l.width);
    set_colour(cr, l.colour);
    polyline(cr, l.p);
  }
  for (const Scene::Circle& c : sc.circles) circle(cr, c);
  for (const Scene::Text& t : sc.texts) text(cr, t, sc.background);
  cairo_surface_flush(surface.get());
  std::string bytes;
  const cairo_status_t st = cairo_surface_write_to_png_stream(surface.get(), append_bytes, &bytes);
  if (st != CAIRO_STATUS_SUCCESS) {
    *error = std::string("cannot encode the picture: ") + cairo_status_to_string(st);
    return {};
  }
  return bytes;
}

bool save_png(const MeshModel& mesh, const PictureOptions& opt, const std::string& path, std::string* error) {
  if (std::string why = validate_mesh_model(mesh); !why.empty()) {
    *error = "invalid mesh: " + why;
    return false;
  }
  std::string why;
  const std::string bytes = png_to_string(build_scene(mesh, opt), &why);
  if (bytes.empty()) {
    *error = why;
    return false;
  }
  base::OutputFile file;
  if (!file.open(path) || !file.write(bytes) || !file.commit()) {
    *error = file.error();
    return false;
  }
  return true;
}

}  // namespace sm::io
