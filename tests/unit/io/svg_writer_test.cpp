// SVG pictures: well-formed XML (read by Python's parser) with one polygon
// per triangle and one polyline per boundary curve (picture_test.cpp tests the scene).
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "geo/sphere.h"
#include "io/svg_writer.h"
#include "io/test_meshes.h"
#include "scratch_dir.h"

using namespace sm;
using namespace sm::io;

namespace {

std::string count_elements(const std::string& svg_path) {
  // A folder of its own: parallel test runs (other build folders) must not share files.
  const sm::testing::ScratchDir dir;
  const std::string script = dir / "count.py";
  std::ofstream(script)
      << "import sys, xml.etree.ElementTree as ET\n"
         "ns = '{http://www.w3.org/2000/svg}'\n"
         "root = ET.parse(sys.argv[1]).getroot()\n"
         "g = {e.get('id'): e for e in root.iter(ns + 'g')}\n"
         "print(len(g['triangles'].findall(ns + 'polygon')), len(g['curves'].findall(ns + 'polyline')))\n";
  const std::string out = dir / "count.txt";
  if (std::system(fmt::format("python3 {} {} > {}", script, svg_path, out).c_str()) != 0) return "parse error";
  std::ifstream in(out);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("svg: planar mesh, one polygon per triangle, one polyline per curve") {
  const MeshModel m = sm::io::testing::grid_square(10);
  std::string error;
  for (PictureColour colour : {PictureColour::None, PictureColour::Quality}) {
    PictureOptions opt;
    opt.view = PictureView::Plane;
    opt.colour = colour;
    const sm::testing::ScratchDir dir;
    REQUIRE(save_svg(m, opt, dir / "plane.svg", &error));
    CHECK(count_elements(dir / "plane.svg") == "200 4\n");
  }
}

TEST_CASE("svg: lon/lat view draws a triangle across the dateline on both sides") {
  // Three triangles on the unit sphere: two near lon 170 and -170 (one of
  // them spanning the dateline), and one far from it.
  MeshModel m;
  const geo::PolarSphere sphere({0, 0, 0}, 1);
  for (geo::LonLat ll : {geo::LonLat{175, 0}, {-175, 0}, {178, 5}, {10, 0}, {20, 0}, {15, 8}})
    m.xyz.push_back(sphere.from_lonlat(ll));
  EntityMesh s;
  s.dim = 2, s.tag = 1, s.type = ElementType::Triangle3;
  s.nodes = {0, 1, 2, 3, 4, 5};
  s.connectivity = {0, 1, 2, 3, 4, 5};
  m.entities.push_back(s);
  PictureOptions opt;
  opt.view = PictureView::LonLat;
  opt.colour = PictureColour::NodeValue;
  opt.node_values = {1, 2, 3, 4, 5, 6};
  std::string error;
  const sm::testing::ScratchDir dir;
  REQUIRE(save_svg(m, opt, dir / "ll.svg", &error));
  CHECK(count_elements(dir / "ll.svg") == "3 0\n");
  const std::string svg = svg_to_string(m, opt);
  CHECK(svg.find("width=\"1600\"") != std::string::npos);
}

TEST_CASE("svg: model points (a sphere's centre) do not stretch the frame") {
  // A triangle near lon 0..10, lat 50..60 plus a point entity at the sphere's
  // centre (lon/lat 0, 0): the picture keeps the triangle's aspect.
  MeshModel m;
  const geo::PolarSphere sphere({0, 0, 0}, 1);
  for (geo::LonLat ll : {geo::LonLat{0, 50}, {10, 50}, {5, 60}}) m.xyz.push_back(sphere.from_lonlat(ll));
  m.xyz.push_back({0, 0, 0});
  EntityMesh p;
  p.dim = 0, p.tag = 1, p.type = ElementType::Point1, p.nodes = {3}, p.connectivity = {3};
  EntityMesh s;
  s.dim = 2, s.tag = 1, s.type = ElementType::Triangle3, s.nodes = {0, 1, 2}, s.connectivity = {0, 1, 2};
  m.entities = {p, s};
  PictureOptions opt;
  opt.width_px = 1000;
  opt.decorations = false;
  const std::string svg = svg_to_string(m, opt);
  // 10 x 10 degrees, x shrunk by cos(55 degrees): 998 px wide, 998 / cos(55) tall, plus the margins.
  CHECK(svg.find("height=\"1742\"") != std::string::npos);
}
