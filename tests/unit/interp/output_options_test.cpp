// The writers' options from scripts: Mesh.NodeCoordinates on MSH files of a PolarSphere
// cap and of a planar model, and the pictures' Mesh.PictureView / PictureColour /
// PictureWidth, with clear errors for values out of range.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp_test_util.h"
#include "scratch_dir.h"

using sm::interp::testing::run_script;

namespace {


// A cap of the Earth in Gmsh's PolarSphere plane, about 3,800 km across, meshed at 300 km.
const char* const kCap =
    "Point(1) = {0, 0, 0}; Point(2) = {0, 0, 6371e3}; PolarSphere(1) = {1, 2};\n"
    "Point(3) = {-0.3, -0.2, 0, 300e3}; Point(4) = {0.3, -0.2, 0, 300e3};\n"
    "Point(5) = {0.2, 0.3, 0, 300e3}; Point(6) = {-0.2, 0.25, 0, 300e3};\n"
    "Line(1) = {3, 4}; Line(2) = {4, 5}; Line(3) = {5, 6}; Line(4) = {6, 3};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Physical Surface(\"sea\") = {1};\n"
    "Mesh 2;\n";

// The node coordinates of an ASCII MSH 2.2 file.
std::vector<std::array<double, 3>> msh22_nodes(const std::string& text) {
  std::istringstream in(text.substr(text.find("$Nodes")));
  std::string tag;
  std::size_t n = 0;
  in >> tag >> n;
  std::vector<std::array<double, 3>> out(n);
  for (auto& x : out) in >> tag >> x[0] >> x[1] >> x[2];
  return out;
}

}  // namespace

TEST_CASE("output options: lon/lat and stereographic node coordinates from a script") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sm_output_options_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string() + "/";
  const auto r = run_script(std::string(kCap) +
                            "Mesh.MshFileVersion = 2.2;\n"
                            "Save \"" + d + "xyz.msh\";\n"
                            "Mesh.NodeCoordinates = 1; Save \"" + d + "ll.msh\";\n"
                            "Mesh.NodeCoordinates = 2; Save \"" + d + "uv.msh\";\n");
  INFO(r.rendered);
  REQUIRE(r.ok);
  const auto xyz = msh22_nodes(sm::testing::read_all(dir / "xyz.msh"));
  const auto ll = msh22_nodes(sm::testing::read_all(dir / "ll.msh"));
  const auto uv = msh22_nodes(sm::testing::read_all(dir / "uv.msh"));
  REQUIRE(xyz.size() > 20);
  REQUIRE(ll.size() == xyz.size());   // physical groups: the centre point is not written
  REQUIRE(uv.size() == xyz.size());
  const double kDeg = 3.14159265358979323846 / 180;
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    const double lon = ll[i][0] * kDeg, lat = ll[i][1] * kDeg;
    CHECK(xyz[i][0] == doctest::Approx(6371e3 * std::cos(lat) * std::cos(lon)).epsilon(1e-9));
    CHECK(xyz[i][2] == doctest::Approx(6371e3 * std::sin(lat)).epsilon(1e-9));
    CHECK(uv[i][0] == doctest::Approx(-std::cos(lat) * std::cos(lon) / (1 + std::sin(lat))).epsilon(1e-9));
    CHECK(uv[i][1] == doctest::Approx(-std::cos(lat) * std::sin(lon) / (1 + std::sin(lat))).epsilon(1e-9));
    CHECK(ll[i][2] == 0);
    CHECK(uv[i][2] == 0);
    // The cap's corners are within |u|, |v| <= 0.3.
    CHECK(std::abs(uv[i][0]) <= 0.3 + 1e-9);
  }
  fs::remove_all(dir);
}

TEST_CASE("output options: errors for lon/lat of a planar model and values out of range") {
  const std::string square =
      "Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {1, 1, 0, 0.2};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
      "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1}; Mesh 2;\n";
  const std::string out = std::filesystem::temp_directory_path() / ("sm_oo_" + std::to_string(::getpid()));
  {
    const auto r = run_script(square + "Mesh.NodeCoordinates = 1; Save \"" + out + ".msh\";\n");
    CHECK_FALSE(r.ok);
    CHECK(r.rendered.find("lon/lat node coordinates need a mesh on a sphere") != std::string::npos);
    CHECK(r.rendered.find("[file-write-error]") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out + ".msh"));
  }
  for (const char* bad : {"Mesh.NodeCoordinates = 3;", "Mesh.PictureView = 2;", "Mesh.PictureColour = -1;",
                          "Mesh.PictureWidth = 8;"}) {
    CAPTURE(bad);
    const bool picture = std::string(bad).find("Picture") != std::string::npos;
    const auto r = run_script(square + bad + " Save \"" + out + (picture ? ".png" : ".msh") + "\";\n");
    CHECK_FALSE(r.ok);
    CHECK(r.rendered.find(std::string(bad).substr(0, std::string(bad).find(' '))) != std::string::npos);
  }
}

TEST_CASE("output options: the stereographic picture of the cap keeps its shape") {
  // In the PolarSphere plane the cap is the quadrilateral of its corner points: its frame
  // is 0.6 wide and 0.5 tall, so the picture is 5/6 as tall as wide (plus the margins).
  const std::string svg = std::filesystem::temp_directory_path() / ("sm_oo_cap_" + std::to_string(::getpid()) + ".svg");
  const auto r = run_script(std::string(kCap) + "Mesh.PictureView = 1; Mesh.PictureWidth = 602;\n"
                            "Mesh.PictureColour = 2; Save \"" + svg + "\";\n");
  INFO(r.rendered);
  REQUIRE(r.ok);
  const std::string text = sm::testing::read_all(svg);
  // The map's frame (the clip rectangle, margins included); the legend strip is below it.
  CHECK(text.find("<rect x=\"0.00\" y=\"0.00\" width=\"602.00\" height=\"502.00\"/>") != std::string::npos);
  CHECK(text.find(">size: mean edge length (km, log scale)</text>") != std::string::npos);
  std::filesystem::remove(svg);
}

TEST_CASE("output options: Mesh.PictureBox zooms, is read back, and refuses boxes that frame nothing") {
  // The cap spans about lon -45..45 around the pole; a box over part of it draws fewer
  // triangles than the whole picture, in a lon/lat frame of the box's shape.
  const std::string dir = std::filesystem::temp_directory_path() / ("sm_oo_box_" + std::to_string(::getpid()));
  const auto r = run_script(std::string(kCap) + "Mesh.PictureWidth = 500; Save \"" + dir + "_whole.svg\";\n" +
                            "Mesh.PictureBox = {170, -170, 60, 80};\n"
                            "b[] = Mesh.PictureBox; Printf(\"%g %g %g %g\", b[0], b[1], b[2], b[3]);\n"
                            "Mesh.PictureBox = {0, 40, 65, 80}; Save \"" + dir + "_zoom.svg\";\n");
  INFO(r.rendered);
  REQUIRE(r.ok);
  CHECK(r.out.find("170 -170 60 80") != std::string::npos);
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  const std::string whole = sm::testing::read_all(dir + "_whole.svg");
  const std::string zoom = sm::testing::read_all(dir + "_zoom.svg");
  CHECK(count(zoom, "<polygon") > 0);
  CHECK(count(zoom, "<polygon") < count(whole, "<polygon"));
  CHECK(zoom.find(">20\u00b0E</text>") != std::string::npos);   // a labelled meridian of the box
  // Colour by criterion without a size field: an error at that Save, naming the option.
  const auto c = run_script(std::string(kCap) + "Mesh.PictureColour = 3; Save \"" + dir + "_criterion.svg\";\n");
  CHECK_FALSE(c.ok);
  CHECK(c.rendered.find("Mesh.PictureColour = 3: size and criterion need a size field") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "_criterion.svg"));
  for (const char* suffix : {"_whole.svg", "_zoom.svg"}) std::filesystem::remove(dir + suffix);
  for (const char* bad : {"Mesh.PictureBox = {0, 10, 40, 30};", "Mesh.PictureBox = {0, 10, -95, 30};",
                          "Mesh.PictureBox = {0, 10, 40};", "Mesh.PictureBox = {5, 5, 0, 1};"}) {
    CAPTURE(bad);
    const auto e = run_script(std::string(bad) + "\n");
    CHECK_FALSE(e.ok);
    CHECK(e.rendered.find("1:19: error:") != std::string::npos);
    CHECK(e.rendered.find("[invalid-option-value]") != std::string::npos);
  }
}

TEST_CASE("output options: Mesh.PictureColour 3 colours by the Min's input that sets the size, named") {
  // Two criteria in a Min: FineField (smaller for x < 0.4) and CoarseField. The legend names
  // both, through the Min behind the mesher's checked background field.
  const std::string svg =
      std::filesystem::temp_directory_path() / ("sm_oo_crit_" + std::to_string(::getpid()) + ".svg");
  const auto r = run_script(
      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
      "CoarseField = 1; FineField = 2;\n"
      "Field[1] = MathEval; Field[1].F = \"0.1\";\n"
      "Field[2] = MathEval; Field[2].F = \"0.02 + 0.2 * x\";\n"
      "Field[3] = Min; Field[3].FieldsList = {1, 2}; Background Field = 3;\n"
      "Mesh 2; Mesh.PictureColour = 3; Save \"" + svg + "\";\n");
  INFO(r.rendered);
  REQUIRE(r.ok);
  const std::string text = sm::testing::read_all(svg);
  CHECK(text.find(">CoarseField: Field[1] (MathEval)</text>") != std::string::npos);
  CHECK(text.find(">FineField: Field[2] (MathEval)</text>") != std::string::npos);
  std::filesystem::remove(svg);
}
