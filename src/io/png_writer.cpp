// PNG pictures of meshes (see png_writer.h): the shared Scene drawn with cairo.
#include "io/png_writer.h"

#include <cairo.h>

#include <cmath>
#include <memory>

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
  cairo_set_line_width(cr, sc.curve_width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  set_colour(cr, sc.curve);
  for (const std::vector<Vec2>& line : sc.polylines) {
    if (line.empty()) continue;
    cairo_move_to(cr, line[0].x, line[0].y);
    for (std::size_t k = 1; k < line.size(); ++k) cairo_line_to(cr, line[k].x, line[k].y);
    cairo_stroke(cr);
  }
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
