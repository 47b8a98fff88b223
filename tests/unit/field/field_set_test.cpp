#include "field/field_set.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>

#include <doctest/doctest.h>

#include "field/error.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;
using sm::field::testing::eval1;

TEST_CASE("field set: newf, delete, duplicate ids") {
  FieldSet fs;
  CHECK(fs.next_id() == 1);
  fs.define(3, "Box");
  CHECK(fs.next_id() == 4);
  CHECK_THROWS_AS(fs.define(3, "Ball"), FieldError);
  fs.remove(3);
  CHECK(!fs.contains(3));
  fs.define(3, "Ball");
  CHECK(fs.options(3).kind().name == "Ball");
  CHECK_THROWS_AS(fs.set(9, "VIn", 1.0), FieldError);
}

TEST_CASE("field set: a reference to a missing field is a typed error naming it") {
  FieldSet fs;
  fs.define(1, "Min");
  fs.set(1, "FieldsList", std::vector<double>{2, 5});
  fs.define(2, "Box");
  try {
    fs.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::MissingField);
    CHECK(e.field_id == 1);
    CHECK(e.ids == std::vector<int>{5});
  }
  // Threshold's InField defaults to 0, which does not exist.
  fs.define(3, "Threshold");
  CHECK_THROWS_AS(fs.build(3, {}), FieldError);
  // MathEval's F<n> references are checked too.
  fs.define(4, "MathEval");
  fs.set(4, "F", std::string("F2 + F8"));
  try {
    fs.build(4, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::MissingField);
    CHECK(e.ids == std::vector<int>{8});
  }
}

TEST_CASE("field set: cycles are typed errors listing the loop") {
  FieldSet fs;
  fs.define(1, "Min");
  fs.set(1, "FieldsList", std::vector<double>{2});
  fs.define(2, "Threshold");
  fs.set(2, "InField", 3.0);
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("F1 * 2"));
  try {
    fs.build(1, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::Cycle);
    CHECK(e.ids == std::vector<int>{1, 2, 3, 1});
    CHECK(std::string(e.what()).find("Field[1] -> Field[2] -> Field[3] -> Field[1]") != std::string::npos);
  }
  FieldSet self;
  self.define(4, "Min");
  self.set(4, "FieldsList", std::vector<double>{4});
  try {
    self.build(4, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::Cycle);
    CHECK(e.ids == std::vector<int>{4, 4});
  }
}

TEST_CASE("field set: a shared input is built once and a diamond is not a cycle") {
  FieldSet fs;
  fs.define(1, "Ball");
  fs.set(1, "Radius", 1.0);
  fs.set(1, "VIn", 2.0);
  fs.set(1, "VOut", 5.0);
  fs.define(2, "MathEval");
  fs.set(2, "F", std::string("F1 + 1"));
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("F1 * 3"));
  fs.define(4, "Max");
  fs.set(4, "FieldsList", std::vector<double>{2, 3});
  BuiltFields b = fs.build(4, {});
  CHECK(b.ids() == std::vector<int>{1, 2, 3, 4});
  std::vector<Vec3> p = {{0, 0, 0}, {3, 0, 0}};
  std::vector<double> h(2);
  b.get(4)->eval(p, h);
  CHECK(h[0] == 6);
  CHECK(h[1] == 15);
}

namespace {

const double lc = .15;
const std::vector<Vec3> t10_points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.2, 0.5, 0}};

// Gmsh tutorial t10's fields (tests/data/field/t10.geo). Curve samples as
// Gmsh takes them on an unmeshed curve: t = i/(N-1), i = 1..N-2.
BuildContext t10_context() {
  BuildContext ctx;
  ctx.point_position = [](int tag) -> std::optional<Vec3> {
    if (tag < 1 || tag > 5) return std::nullopt;
    return t10_points[static_cast<std::size_t>(tag - 1)];
  };
  ctx.curve_samples = [](int tag, int n) -> std::optional<std::vector<Vec3>> {
    if (tag != 1 && tag != 2) return std::nullopt;
    const Vec3 a = t10_points[static_cast<std::size_t>(tag - 1)], b = t10_points[static_cast<std::size_t>(tag)];
    std::vector<Vec3> s;
    for (int i = 1; i <= n - 2; ++i) s.push_back(a + (b - a) * (static_cast<double>(i) / (n - 1)));
    return s;
  };
  return ctx;
}

FieldSet t10_fields() {
  FieldSet fs;
  fs.define(1, "Distance");
  fs.set(1, "PointsList", std::vector<double>{5});
  fs.set(1, "CurvesList", std::vector<double>{2});
  fs.set(1, "NumPointsPerCurve", 100.0);
  fs.define(2, "Threshold");
  fs.set(2, "InField", 1.0);
  fs.set(2, "SizeMin", lc / 30);
  fs.set(2, "SizeMax", lc);
  fs.set(2, "DistMin", 0.15);
  fs.set(2, "DistMax", 0.5);
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("Cos(4*3.14*x) * Sin(4*3.14*y) / 10 + 0.101"));
  fs.define(4, "Distance");
  fs.set(4, "CurvesList", std::vector<double>{1});
  fs.set(4, "NumPointsPerCurve", 100.0);
  fs.define(5, "MathEval");
  fs.set(5, "F", std::string("F4^3 + 0.015"));  // Sprintf("F4^3 + %g", lc / 10)
  fs.define(6, "Box");
  fs.set(6, "VIn", lc / 15);
  fs.set(6, "VOut", lc);
  fs.set(6, "XMin", 0.3);
  fs.set(6, "XMax", 0.6);
  fs.set(6, "YMin", 0.3);
  fs.set(6, "YMax", 0.6);
  fs.set(6, "Thickness", 0.3);
  fs.define(7, "Min");
  fs.set(7, "FieldsList", std::vector<double>{2, 3, 5, 6});
  return fs;
}

}  // namespace

// t10's field set against the formulas of docs/fields.md written out
// independently here (exact distances to the point and the segments stand in
// for Gmsh's 100-sample curves).
TEST_CASE("field set: Gmsh tutorial t10 field set") {
  const BuildContext ctx = t10_context();
  FieldSet fs = t10_fields();

  auto oracle = [&](double x, double y) {
    const double d1 = std::min(std::hypot(x - 0.2, y - 0.5), std::fabs(1 - x));
    const double r = std::clamp((d1 - 0.15) / (0.5 - 0.15), 0.0, 1.0);
    const double f2 = lc / 30 * (1 - r) + lc * r;
    const double f3 = std::cos(4 * 3.14 * x) * std::sin(4 * 3.14 * y) / 10 + 0.101;
    const double f5 = std::pow(std::fabs(y), 3) + 0.015;
    const double dx = std::max({0.3 - x, 0.0, x - 0.6}), dy = std::max({0.3 - y, 0.0, y - 0.6});
    const double db = std::hypot(dx, dy);
    const double f6 = db == 0 ? lc / 15 : db <= 0.3 ? lc / 15 + db / 0.3 * (lc - lc / 15) : lc;
    return std::min({f2, f3, f5, f6});
  };
  std::vector<Vec3> pts;
  for (int i = 1; i < 20; ++i)
    for (int j = 1; j < 20; ++j) pts.push_back({0.05 * i, 0.05 * j, 0});
  const std::vector<double> h = sm::field::testing::eval_field(fs, 7, pts, ctx);
  for (std::size_t k = 0; k < pts.size(); ++k)
    CHECK_MESSAGE(h[k] == doctest::Approx(oracle(pts[k].x, pts[k].y)).epsilon(2e-3),
                  "at " << pts[k].x << "," << pts[k].y);
  // Two spot values by hand: inside the box, the box wins (0.01); at
  // (0.9, 0.9) the sine term of Field[3] is the smallest.
  CHECK(eval1(fs, 7, {0.45, 0.45, 0}, ctx) == doctest::Approx(0.01));
  CHECK(eval1(fs, 7, {0.05, 0.05, 0}, ctx) == doctest::Approx(std::pow(0.05, 3) + 0.015).epsilon(1e-3));
}

// The mesh Gmsh 4.8.4 itself made from t10.geo with this field as background
// (tests/data/field/t10_gmsh_edges.txt): its edge lengths follow our Field[7]
// at the edge midpoints. Gmsh's edges scatter around the target size, so the
// check is statistical: the median ratio is near 1 and most edges are within
// a factor 1.6 of the size.
TEST_CASE("field set: t10 sizes against the edges of Gmsh's own mesh") {
  std::ifstream in(std::string(SM_TEST_DATA) + "/field/t10_gmsh_edges.txt");
  REQUIRE(in);
  std::vector<Vec3> mid;
  std::vector<double> len;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double x, y, l;
    ls >> x >> y >> l;
    mid.push_back({x, y, 0});
    len.push_back(l);
  }
  REQUIRE(mid.size() == 6393);
  const std::vector<double> h = sm::field::testing::eval_field(t10_fields(), 7, mid, t10_context());
  std::vector<double> ratio(mid.size());
  std::size_t close = 0, tight = 0;
  for (std::size_t i = 0; i < mid.size(); ++i) {
    ratio[i] = len[i] / h[i];
    if (ratio[i] > 1 / 1.6 && ratio[i] < 1.6) ++close;
    if (ratio[i] > 1 / 1.25 && ratio[i] < 1.25) ++tight;
  }
  std::nth_element(ratio.begin(), ratio.begin() + static_cast<long>(ratio.size() / 2), ratio.end());
  const double median = ratio[ratio.size() / 2];
  MESSAGE("t10: median edge/size ratio " << median << "; of " << mid.size() << " edges " << close
                                         << " within a factor 1.6, " << tight << " within 1.25");
  CHECK(median > 0.95);
  CHECK(median < 1.05);
  CHECK(close > 0.99 * static_cast<double>(mid.size()));
  CHECK(tight > 0.8 * static_cast<double>(mid.size()));
}

// Evaluation is const and thread-safe: four threads evaluating the same
// built fields (Distance, Threshold, MathEval, Box, Min) concurrently get
// exactly the serial answers.
TEST_CASE("field set: concurrent evaluation of one built field") {
  const BuildContext ctx = t10_context();
  BuiltFields b = t10_fields().build(7, ctx);
  std::vector<Vec3> pts;
  for (int i = 0; i < 20000; ++i) pts.push_back({(i % 137) / 137.0, (i % 71) / 71.0, 0});
  std::vector<double> serial(pts.size());
  b.get(7)->eval(pts, serial);
  std::vector<std::vector<double>> out(4, std::vector<double>(pts.size()));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < out.size(); ++t)
    threads.emplace_back([&, t] {
      for (int rep = 0; rep < 3; ++rep) b.get(7)->eval(pts, out[t]);
    });
  for (std::thread& t : threads) t.join();
  for (const auto& o : out) CHECK(o == serial);
}

// A MathEval syntax error found while listing the F<n> references names the
// field and option, so the interpreter can point at the Field[n].F statement.
TEST_CASE("field set: MathEval parse errors carry field id, option and column") {
  FieldSet fs;
  fs.define(3, "MathEval");
  fs.set(3, "F", std::string("F1 + 2*-x"));
  fs.define(4, "Min");
  fs.set(4, "FieldsList", std::vector<double>{3});
  try {
    fs.build(4, {});
    FAIL("expected an error");
  } catch (const FieldError& e) {
    CHECK(e.code() == FieldErrc::ParseError);
    CHECK(e.field_id == 3);
    CHECK(e.option == "F");
    CHECK(e.column == 8);
  }
}

namespace {

// The set-up stages a build reports: "begin NAME" and "end", in order.
class SetupStageLog final : public Progress {
 public:
  std::vector<std::string> events;
  void begin(std::string_view name, std::uint64_t) override { events.push_back("begin " + std::string(name)); }
  void update(std::uint64_t) override {}
  void end() override { events.push_back("end"); }
};

}  // namespace

TEST_CASE("field set: each kind's set-up is one stage, its references' stages before it, not nested") {
  FieldSet fs;
  fs.define(1, "Ball");
  fs.set(1, "Radius", 1.0);
  fs.define(2, "MathEval");
  fs.set(2, "F", std::string("F1 + 1"));
  fs.define(3, "Max");
  fs.set(3, "FieldsList", std::vector<double>{1, 2});
  SetupStageLog log;
  BuildContext ctx;
  ctx.setup_clock = &log;
  fs.build(3, ctx);
  CHECK(log.events == std::vector<std::string>{"begin field Ball", "end", "begin field MathEval", "end",
                                               "begin field Max", "end"});
  // A kind that fails still ends its stage.
  fs.define(4, "Structured");
  fs.set(4, "FileName", std::string("/nonexistent/grid.dat"));
  log.events.clear();
  CHECK_THROWS_AS(fs.build(4, ctx), FieldError);
  CHECK(log.events == std::vector<std::string>{"begin field Structured", "end"});
}
