// PNG pictures: a valid PNG (signature, IHDR size) that cairo reads back, the same frame as
// the SVG picture, and coastline-coloured pixels where the boundary curves are.
#include <doctest/doctest.h>

#include <cairo.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "geo/sphere.h"
#include "io/png_writer.h"
#include "io/test_meshes.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

namespace {

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint32_t be32(const std::string& b, std::size_t at) {
  return (std::uint32_t(std::uint8_t(b[at])) << 24) | (std::uint32_t(std::uint8_t(b[at + 1])) << 16) |
         (std::uint32_t(std::uint8_t(b[at + 2])) << 8) | std::uint32_t(std::uint8_t(b[at + 3]));
}

// A picture read back with cairo: its size and pixel colours.
struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> px;
  Rgb at(int x, int y) const { return px[std::size_t(y) * width + x]; }
};

Image read_png(const std::string& path) {
  Image img;
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    img.width = cairo_image_surface_get_width(s);
    img.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        std::uint32_t v;
        std::memcpy(&v, data + std::size_t(y) * stride + 4 * x, 4);
        img.px.push_back({std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)});
      }
  }
  cairo_surface_destroy(s);
  return img;
}

// Coastline red (#b2182b), allowing for antialiasing against the light fills.
bool reddish(Rgb c) { return c.r > 140 && c.r > c.g + 60 && c.r > c.b + 60; }

std::size_t count_reddish(const Image& img) {
  std::size_t n = 0;
  for (Rgb c : img.px) n += reddish(c);
  return n;
}

// A path in this run's own folder: fixed /tmp names raced with the same test of other
// checkouts running at once.
std::string png_writer_tmp(const char* name) {
  static const sm::testing::ScratchDir dir;
  return (dir.path / name).string();
}

}  // namespace

TEST_CASE("png: planar mesh, signature, size and coastline pixels") {
  const MeshModel m = sm::io::testing::grid_square(10);
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.width_px = 400;
  opt.decorations = false;   // the map alone: the legend strip would add height
  std::string error;
  const std::string path = png_writer_tmp("sm_png_plane.png");
  REQUIRE(save_png(m, opt, path, &error));
  const std::string bytes = read_bytes(path);
  REQUIRE(bytes.size() > 33);
  CHECK(bytes.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
  CHECK(bytes.substr(12, 4) == "IHDR");
  CHECK(be32(bytes, 16) == 400);
  CHECK(be32(bytes, 20) == 400);
  const Image img = read_png(path);
  REQUIRE(img.width == 400);
  REQUIRE(img.height == 400);
  // The four sides: a stroke 1 px wide inside a 1 px margin, antialiased over two pixels.
  CHECK(count_reddish(img) > 4 * 390);
  CHECK(!reddish(img.at(200, 200)));   // the middle is mesh, not coastline
  CHECK(reddish(img.at(200, 0)));
  CHECK(reddish(img.at(0, 200)));
  CHECK(reddish(img.at(399, 200)));
  CHECK(reddish(img.at(200, 399)));
}

TEST_CASE("png: sphere mesh in lon/lat view, coastline across the middle") {
  const MeshModel m = sm::io::testing::sphere_patch(10);
  for (PictureColour colour : {PictureColour::None, PictureColour::Quality}) {
    PictureOptions opt;
    opt.view = PictureView::LonLat;
    opt.colour = colour;
    opt.width_px = 3006;   // coastlines 3 px wide, a 3 px margin
    opt.decorations = false;
    std::string error;
    const std::string path = png_writer_tmp("sm_png_sphere.png");
    REQUIRE(save_png(m, opt, path, &error));
    const Image img = read_png(path);
    REQUIRE(img.width == 3006);
    // 20 x 10 degrees, x shrunk by cos(45 degrees): 3000 / (20 cos 45) = 212.1 px per degree.
    const double per_degree = 3000 / (20 * std::cos(45 * 3.14159265358979323846 / 180));
    REQUIRE(img.height == std::lround(10 * per_degree + 6));
    // lat 45 is the middle row: the curve covers 1.5 rows either side of it.
    const int mid = static_cast<int>(3 + 5 * per_degree);
    CHECK(reddish(img.at(1503, mid)));
    CHECK(!reddish(img.at(1503, mid - 50)));
    CHECK(!reddish(img.at(1503, mid + 50)));
    // The whole mid curve is drawn: every column has coastline red there.
    int columns = 0;
    for (int x = 3; x < 3003; ++x) columns += reddish(img.at(x, mid));   // lon -10..10
    CHECK(columns == 3000);
    // And nothing else is red inside: rows a quarter and three quarters down have none.
    int stray = 0;
    for (int x = 20; x < 2980; ++x)
      stray += reddish(img.at(x, static_cast<int>(3 + 2.5 * per_degree))) +
               reddish(img.at(x, static_cast<int>(3 + 7.5 * per_degree)));
    CHECK(stray == 0);
  }
}

TEST_CASE("png: stereographic view and the scene shared with SVG") {
  const MeshModel m = sm::io::testing::sphere_patch(6);
  PictureOptions opt;
  opt.view = PictureView::Stereographic;
  opt.width_px = 300;
  const Scene sc = build_scene(m, opt);
  CHECK(sc.triangles.size() == 72);
  CHECK(sc.polylines.size() == 5);
  std::string error;
  const std::string bytes = png_to_string(sc, &error);
  REQUIRE(!bytes.empty());
  CHECK(png_to_string(build_scene(m, opt), &error) == bytes);   // byte-identical on a second run
  CHECK(be32(bytes, 16) == 300);
  CHECK(be32(bytes, 20) == static_cast<std::uint32_t>(std::lround(sc.height)));
}

TEST_CASE("png: a missing directory is a clear error and nothing is written") {
  const MeshModel m = sm::io::testing::grid_square(2);
  PictureOptions opt;
  opt.view = PictureView::Plane;
  std::string error;
  CHECK(!save_png(m, opt, "/nonexistent-dir/x.png", &error));
  CHECK(error == "No such file or directory");   // the caller names the file
}

TEST_CASE("picture: triangle edges only where the triangles are big enough to show them") {
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.width_px = 200;
  opt.decorations = false;
  // 100 x 100 cells on 198 px: edges of 2-3 px, too small: fills only.
  CHECK(build_scene(sm::io::testing::grid_square(100), opt).edge_width == 0);
  // 10 x 10 cells: 20 px edges, drawn.
  CHECK(build_scene(sm::io::testing::grid_square(10), opt).edge_width > 0);
  // The dense picture has no edge colour and no background seams inside the mesh: every
  // pixel is the fill colour (within the rounding of antialiased overlaps).
  std::string error;
  opt.colour = PictureColour::None;
  REQUIRE(save_png(sm::io::testing::grid_square(100), opt, png_writer_tmp("sm_png_dense.png"), &error));
  const Image img = read_png(png_writer_tmp("sm_png_dense.png"));
  int fill = 0;
  for (int y = 20; y < 180; ++y)
    for (int x = 20; x < 180; ++x) {
      const Rgb c = img.at(x, y);
      fill += std::abs(c.r - 0xdf) <= 2 && std::abs(c.g - 0xe9) <= 2 && std::abs(c.b - 0xf2) <= 2;
    }
  CHECK(fill == 160 * 160);
}

TEST_CASE("picture: colouring by size on a log scale, smallest blue, largest red") {
  // grid_square(8) with x stretched quadratically: cells grow from left to right.
  MeshModel m = sm::io::testing::grid_square(8);
  for (Vec3& x : m.xyz) x.x = x.x * x.x * 4;
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.colour = PictureColour::Size;
  const Scene sc = build_scene(m, opt);
  REQUIRE(sc.triangles.size() == 128);
  // Scene triangles follow the entity's order: cell (i, j) gives triangles 2(8j + i), +1.
  const Rgb first = sc.triangles[0].fill, last = sc.triangles[2 * 7 + 1].fill;
  CHECK(first.b > first.r);    // the smallest cells: blue end of the ramp
  CHECK(last.r > last.b);      // the largest: red end
  CHECK(first == Rgb{49, 54, 149});
  CHECK(last == Rgb{165, 0, 38});
}
