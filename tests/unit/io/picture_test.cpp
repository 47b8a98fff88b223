// The picture's scene: a box clips triangles and curves and frames the picture (across the
// dateline too, and in the stereographic view), the graticule's lines and labels, one legend
// entry per physical curve group, the colour bar's range, the worst triangles circled,
// category colours, and the box's checks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "exact/quality.h"
#include "geo/sphere.h"
#include "io/picture.h"
#include "io/svg_writer.h"
#include "io/test_meshes.h"

namespace {

using sm::io::MeshModel;
using sm::io::PictureBox;
using sm::io::PictureColour;
using sm::io::PictureOptions;
using sm::io::PictureView;
using sm::io::Scene;

// sphere_patch turned by 180 degrees about the pole: lon 170..190 (across the dateline).
MeshModel dateline_patch(int n) {
  MeshModel m = sm::io::testing::sphere_patch(n);
  for (sm::Vec3& x : m.xyz) x = {-x.x, -x.y, x.z};
  return m;
}

PictureBox box(double w, double e, double s, double n) {
  PictureBox b;
  REQUIRE(sm::io::normalise_picture_box(w, e, s, n, &b) == sm::io::PictureBoxProblem::None);
  return b;
}

bool has_text(const std::vector<Scene::Text>& texts, const std::string& s) {
  return std::any_of(texts.begin(), texts.end(), [&](const Scene::Text& t) { return t.text == s; });
}

}  // namespace

TEST_CASE("picture: a box keeps the triangles and curve segments that reach into it") {
  // sphere_patch(10): cells of 2 x 1 degrees over lon -10..10, lat 40..50; the box
  // lon 1..9, lat 41.5..44.5 meets the cells of columns 5..9 and rows 1..4.
  const MeshModel m = sm::io::testing::sphere_patch(10);
  PictureOptions opt;
  opt.view = PictureView::LonLat;
  opt.width_px = 1000;
  opt.box = box(1, 9, 41.5, 44.5);
  const Scene sc = build_scene(m, opt);
  CHECK(sc.triangles.size() == 2 * 5 * 4);
  CHECK(sc.polylines.empty());   // the sides and the lat 45 curve are all outside
  // The frame is the box, x shrunk by cos(43 degrees): 998 px for 8 degrees of longitude.
  const double scale = 998 / (8 * std::cos(43 * sm::geo::kDegToRad));
  CHECK(sc.map.hi.x - sc.map.lo.x == doctest::Approx(998));
  CHECK(sc.map.hi.y - sc.map.lo.y == doctest::Approx(3 * scale));
  // Up to lat 45.5 the middle curve's segments over lon 0..10 come in, as one chain.
  opt.box = box(1, 9, 41.5, 45.5);
  const Scene with_curve = build_scene(m, opt);
  REQUIRE(with_curve.polylines.size() == 1);
  CHECK(with_curve.polylines[0].p.size() == 6);
}

TEST_CASE("picture: a box across the dateline, in lon/lat and stereographic views") {
  const MeshModel m = dateline_patch(10);   // cells over lon 170..190
  PictureOptions opt;
  opt.width_px = 800;
  opt.box = box(175, -175, 41.5, 44.5);     // W > E: 175 to 185
  CHECK(opt.box->east == 185);
  for (PictureView view : {PictureView::LonLat, PictureView::Stereographic}) {
    opt.view = view;
    const Scene sc = build_scene(m, opt);
    CHECK(sc.triangles.size() == 2 * 6 * 4);   // columns 2..7 (lon 174..186), rows 1..4
    for (const Scene::Triangle& t : sc.triangles)
      for (const sm::Vec2& p : t.p) CHECK((std::isfinite(p.x) && std::isfinite(p.y)));
  }
  // Without a box the lon/lat view draws the patch on both sides of the frame (-180..180).
  opt.box.reset();
  opt.view = PictureView::LonLat;
  CHECK(build_scene(m, opt).triangles.size() > 200);
}

TEST_CASE("picture: graticule lines at round steps, labelled in degrees") {
  CHECK(sm::io::graticule_step(360) == 60);
  CHECK(sm::io::graticule_step(168) == 30);
  CHECK(sm::io::graticule_step(20) == 5);
  CHECK(sm::io::graticule_step(10) == 2);
  CHECK(sm::io::graticule_step(1) == doctest::Approx(0.2));
  const MeshModel m = sm::io::testing::sphere_patch(10);
  PictureOptions opt;
  opt.view = PictureView::LonLat;
  opt.width_px = 1000;
  const Scene sc = build_scene(m, opt);
  // lon -10..10 by 5 and lat 40..50 by 2, the frame's edges left out.
  std::vector<double> meridians, parallels;
  for (const Scene::GridLine& g : sc.graticule) (g.meridian ? meridians : parallels).push_back(g.value);
  CHECK(meridians == std::vector<double>{-5, 0, 5});
  CHECK(parallels == std::vector<double>{42, 44, 46, 48});
  // The meridian 0 runs down the middle of the map, the parallel 44 four tenths up.
  for (const Scene::GridLine& g : sc.graticule) {
    if (g.meridian && g.value == 0)
      for (const sm::Vec2& p : g.p) CHECK(p.x == doctest::Approx(0.5 * (sc.map.lo.x + sc.map.hi.x)));
    if (!g.meridian && g.value == 44)
      CHECK(g.p[0].y == doctest::Approx(sc.map.hi.y - 0.4 * (sc.map.hi.y - sc.map.lo.y)));
  }
  for (const char* label : {"5\u00b0W", "0\u00b0", "5\u00b0E", "42\u00b0N", "48\u00b0N"})
    CHECK(has_text(sc.map_labels, label));
  for (const Scene::Text& t : sc.map_labels) {
    CHECK(t.at.x >= sc.map.lo.x);
    CHECK(t.at.y <= sc.map.hi.y);
  }
  // A planar model has no graticule; neither has a picture without decorations.
  PictureOptions plane;
  plane.view = PictureView::Plane;
  CHECK(build_scene(sm::io::testing::grid_square(4), plane).graticule.empty());
  opt.decorations = false;
  CHECK(build_scene(m, opt).graticule.empty());
}

TEST_CASE("picture: one legend entry and colour per physical curve group") {
  MeshModel m = sm::io::testing::sphere_patch(4);
  // Curves 1, 3, 4 stay "coast" (group 5); curve 2 goes in an unnamed group 8, the
  // middle curve 5 in "open" (group 9).
  for (sm::io::EntityMesh& e : m.entities) {
    if (e.dim == 1 && e.tag == 2) e.physical_tags = {8};
    if (e.dim == 1 && e.tag == 5) e.physical_tags = {9};
  }
  m.physicals.push_back({1, 9, "open"});
  m.physicals.push_back({1, 8, ""});
  PictureOptions opt;
  opt.view = PictureView::LonLat;
  const Scene sc = build_scene(m, opt);
  // Plain fills: no key; the groups by tag.
  CHECK(sc.legend == std::vector<std::string>{"coast", "Physical Curve 8", "open"});
  for (const std::string& name : sc.legend) CHECK(has_text(sc.texts, name));
  std::vector<sm::io::Rgb> colours;
  for (const Scene::Curve& c : sc.polylines) {
    const sm::io::Rgb col = sc.curve_styles[c.style].colour;
    if (std::find(colours.begin(), colours.end(), col) == colours.end()) colours.push_back(col);
  }
  CHECK(colours.size() == 3);
  // The legend strip is below the map.
  for (const Scene::Text& t : sc.texts) CHECK(t.at.y > sc.map.hi.y);
  CHECK(sc.height > sc.map.hi.y + 10);
}

TEST_CASE("picture: the colour bar's title and range") {
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.colour = PictureColour::Quality;
  const Scene q = build_scene(sm::io::testing::grid_square(4), opt);
  CHECK(q.bar_title.find("rho") != std::string::npos);
  CHECK(has_text(q.texts, q.bar_title));
  CHECK(q.boxes.size() == 3);   // no bar: one swatch per quality class
  // Size: the range of the triangles' mean edges, in km (the model is in metres).
  MeshModel m = sm::io::testing::grid_square(8);
  for (sm::Vec3& x : m.xyz) x = {x.x * x.x * 4e5, x.y * 1e5, 0};
  double lo = 1e300, hi = 0;
  for (const sm::io::EntityMesh& e : m.entities)
    if (e.type == sm::io::ElementType::Triangle3)
      for (std::size_t k = 0; k < e.connectivity.size(); k += 3) {
        const sm::Vec3 a = m.xyz[e.connectivity[k]], b = m.xyz[e.connectivity[k + 1]], c = m.xyz[e.connectivity[k + 2]];
        const double l = (norm(b - a) + norm(c - b) + norm(a - c)) / 3;
        lo = std::min(lo, l), hi = std::max(hi, l);
      }
  opt.colour = PictureColour::Size;
  const Scene s = build_scene(m, opt);
  CHECK(s.bar_title == "size: mean edge length (km, log scale)");
  CHECK(s.bar_min == doctest::Approx(lo / 1000));
  CHECK(s.bar_max == doctest::Approx(hi / 1000));
  // A fixed range, as for two pictures compared side by side.
  opt.colour_min = 20, opt.colour_max = 200;
  const Scene fixed = build_scene(m, opt);
  CHECK(fixed.bar_min == 20);
  CHECK(fixed.bar_max == 200);
  opt.colour_min = opt.colour_max = 0;
  // A node field: its own range and title.
  opt.colour = PictureColour::NodeValue;
  opt.node_values.assign(m.xyz.size(), 0);
  for (std::size_t i = 0; i < m.xyz.size(); ++i) opt.node_values[i] = 10 + m.xyz[i].y / 1e3;
  opt.node_values_title = "depth (m)";
  const Scene d = build_scene(m, opt);
  CHECK(d.bar_title == "depth (m)");
  CHECK(d.bar_min == doctest::Approx(10));
  CHECK(d.bar_max == doctest::Approx(110));
  CHECK(has_text(d.texts, "depth (m)"));
}

TEST_CASE("picture: a depth bar spans the depths of the triangles drawn, not the whole mesh's") {
  // sphere_patch(10) with depth 1000 + 100 row + column: the box lon 1..9, lat 41.5..44.5
  // draws the cells of columns 5..9 and rows 1..4, whose nodes are columns 5..10 and rows
  // 1..5: depths 1105 to 1510 (the whole mesh: 1000 to 2010).
  const MeshModel m = sm::io::testing::sphere_patch(10);
  PictureOptions opt;
  opt.view = PictureView::LonLat;
  opt.colour = PictureColour::NodeValue;
  opt.node_values_title = "depth (m)";
  opt.node_values.resize(m.xyz.size());
  for (std::size_t v = 0; v < 11 * 11; ++v) opt.node_values[v] = 1000 + 100.0 * double(v / 11) + double(v % 11);
  for (std::size_t v = 11 * 11; v < m.xyz.size(); ++v) opt.node_values[v] = 5000;   // not on a triangle
  const Scene whole = build_scene(m, opt);
  CHECK(whole.bar_min == 1000);
  CHECK(whole.bar_max == 2010);
  opt.box = box(1, 9, 41.5, 44.5);
  const Scene zoom = build_scene(m, opt);
  REQUIRE(zoom.triangles.size() == 2 * 5 * 4);
  CHECK(zoom.bar_min == 1105);
  CHECK(zoom.bar_max == 1510);
  CHECK(has_text(zoom.texts, "1200"));
  CHECK(!has_text(zoom.texts, "2000"));
  // Mesh.PictureColourMin/Max still fix the range.
  opt.colour_min = 0, opt.colour_max = 4000;
  const Scene fixed = build_scene(m, opt);
  CHECK(fixed.bar_min == 0);
  CHECK(fixed.bar_max == 4000);
}

TEST_CASE("picture: quality classes, below the floor, the worst 1%, the rest") {
  using sm::io::QualityClass;
  // 200 triangles: one below the floor, two lowest above it tied (the first by position is
  // the worst 1%'s second member), the rest good.
  std::vector<double> rho(200, 0.9);
  rho[10] = 0.1, rho[20] = 0.5, rho[30] = 0.5, rho[40] = 0.6;
  const std::vector<QualityClass> cls = sm::io::quality_classes(rho, 0.3);
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const QualityClass want = i == 10 ? QualityClass::BelowFloor : i == 20 ? QualityClass::WorstPercent
                                                                           : QualityClass::Rest;
    CHECK(cls[i] == want);
  }
  // Below the floor is below the floor however many: here 3 of 100, beyond the worst 1%.
  std::vector<double> many(100, 0.95);
  many[1] = many[50] = many[99] = 0.2;
  std::size_t below = 0, worst = 0;
  for (QualityClass c : sm::io::quality_classes(many, 0.3))
    below += c == QualityClass::BelowFloor, worst += c == QualityClass::WorstPercent;
  CHECK(below == 3);
  CHECK(worst == 0);
  CHECK(sm::io::quality_classes({}, 0.3).empty());
}

TEST_CASE("picture: quality fills flag exactly the triangles below the floor") {
  // grid_square(4) with node (1, 1) pulled next to node (2, 2): slivers around it.
  MeshModel m = sm::io::testing::grid_square(4);
  m.xyz[6] = {0.49, 0.48, 0};
  std::size_t below = 0, total = 0;
  for (const sm::io::EntityMesh& e : m.entities)
    if (e.type == sm::io::ElementType::Triangle3)
      for (std::size_t k = 0; k < e.connectivity.size(); k += 3, ++total)
        below += sm::rho(m.xyz[e.connectivity[k]], m.xyz[e.connectivity[k + 1]], m.xyz[e.connectivity[k + 2]]) < 0.3;
  REQUIRE(below > 0);
  REQUIRE(below < total);
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.colour = PictureColour::Quality;
  const sm::io::Rgb red = sm::io::quality_colour(sm::io::QualityClass::BelowFloor);
  const sm::io::Rgb orange = sm::io::quality_colour(sm::io::QualityClass::WorstPercent);
  const sm::io::Rgb calm = sm::io::quality_colour(sm::io::QualityClass::Rest);
  auto count = [](const Scene& sc, sm::io::Rgb c) {
    return static_cast<std::size_t>(std::count_if(sc.triangles.begin(), sc.triangles.end(),
                                                  [&](const Scene::Triangle& t) { return t.fill == c; }));
  };
  const Scene sc = build_scene(m, opt);
  REQUIRE(sc.triangles.size() == total);
  CHECK(count(sc, red) == below);
  CHECK(count(sc, orange) == 0);   // the worst 1% (one triangle) is below the floor
  CHECK(count(sc, calm) == total - below);
  REQUIRE(sc.legend.size() >= 3);
  CHECK(sc.legend[0].rfind(fmt::format("below the floor 0.3: {} triangles", below), 0) == 0);
  CHECK(sc.legend[1] == "worst 1%: none");
  // No floor: no red, and the one worst triangle in orange.
  opt.quality_floor = 0;
  const Scene no_floor = build_scene(m, opt);
  CHECK(count(no_floor, red) == 0);
  CHECK(count(no_floor, orange) == 1);
  // The SVG's triangles draw the red fill exactly that many times.
  const std::string svg = sm::io::svg_to_string(sc);
  const std::string fill = fmt::format("fill=\"#{:02x}{:02x}{:02x}\"/>", red.r, red.g, red.b);
  std::size_t fills = 0;
  for (std::size_t at = svg.find("<polygon"); at != std::string::npos; at = svg.find("<polygon", at + 1))
    fills += svg.compare(svg.find(" fill=", at), fill.size() + 1, " " + fill) == 0;
  CHECK(fills == below);
}

TEST_CASE("picture: the worst triangles circled, lowest rho first") {
  // grid_square(4) with node (1, 1) pulled next to node (2, 2): the triangles around it
  // become slivers.
  MeshModel m = sm::io::testing::grid_square(4);
  m.xyz[6] = {0.49, 0.48, 0};
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.worst = 2;
  const Scene sc = build_scene(m, opt);
  REQUIRE(sc.marks.size() == 2);
  double worst = 1;
  for (const sm::io::EntityMesh& e : m.entities)
    if (e.type == sm::io::ElementType::Triangle3)
      for (std::size_t k = 0; k < e.connectivity.size(); k += 3)
        worst = std::min(worst, sm::rho(m.xyz[e.connectivity[k]], m.xyz[e.connectivity[k + 1]],
                                              m.xyz[e.connectivity[k + 2]]));
  REQUIRE(!sc.legend.empty());
  CHECK(sc.legend[0].find(fmt::format("rho {:.2f} to", worst)) != std::string::npos);
  REQUIRE(!sc.circles.empty());   // the legend's sample circle
  opt.worst = 0;
  CHECK(build_scene(m, opt).marks.empty());
}

TEST_CASE("picture: categories, one colour each, named in the legend") {
  MeshModel m = sm::io::testing::grid_square(4);
  PictureOptions opt;
  opt.view = PictureView::Plane;
  opt.colour = PictureColour::Category;
  opt.node_values.resize(m.xyz.size());
  for (std::size_t i = 0; i < m.xyz.size(); ++i) opt.node_values[i] = m.xyz[i].x < 0.5 ? 3 : 7;
  opt.category_names = {{3, "ShoreField: Field[3] (Threshold)"}};
  const Scene sc = build_scene(m, opt);
  CHECK(sc.legend == std::vector<std::string>{"coast", "ShoreField: Field[3] (Threshold)", "7"});
  std::vector<sm::io::Rgb> fills;
  for (const Scene::Triangle& t : sc.triangles)
    if (std::find(fills.begin(), fills.end(), t.fill) == fills.end()) fills.push_back(t.fill);
  CHECK(fills.size() == 2);
  CHECK(sc.bar_title.empty());
}

TEST_CASE("picture: boxes that frame nothing are refused with the reason") {
  PictureBox b;
  using Problem = sm::io::PictureBoxProblem;
  CHECK(sm::io::normalise_picture_box(0, 10, 40, 30, &b) == Problem::SouthNotBelowNorth);
  CHECK(sm::io::normalise_picture_box(0, 10, -95, 30, &b) == Problem::Latitudes);
  CHECK(sm::io::normalise_picture_box(5, 5, 0, 1, &b) == Problem::NoWidth);
  CHECK(sm::io::normalise_picture_box(0, 400, 0, 1, &b) == Problem::Longitudes);
  CHECK(sm::io::normalise_picture_box(-300, 200, 0, 1, &b) == Problem::TooWide);
  CHECK(sm::io::normalise_picture_box(0, 10, 0, std::nan(""), &b) == Problem::NotFinite);
  REQUIRE(sm::io::normalise_picture_box(170, -170, 0, 1, &b) == Problem::None);
  CHECK(b.west == 170);
  CHECK(b.east == 190);
}

TEST_CASE("picture: the SVG is the same bytes on every run, escaped text") {
  MeshModel m = sm::io::testing::sphere_patch(6);
  m.physicals[0].name = "coast & <shore>";
  PictureOptions opt;
  opt.view = PictureView::Stereographic;
  opt.worst = 3;
  const std::string a = sm::io::svg_to_string(m, opt);
  CHECK(a == sm::io::svg_to_string(m, opt));
  CHECK(a.find(">coast &amp; &lt;shore&gt;</text>") != std::string::npos);
  CHECK(a.find("nan") == std::string::npos);
}
