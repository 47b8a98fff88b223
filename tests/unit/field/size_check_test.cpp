#include "field/size_check.h"

#include <cmath>
#include <vector>

#include <doctest/doctest.h>

#include "field/error.h"

using namespace sm;
using namespace sm::field;

namespace {

// Gives h = x at each point (so the sizes are chosen by the points).
class XField final : public SizeField {
 public:
  void eval(std::span<const Vec3> pts, std::span<double> h) const override {
    for (std::size_t i = 0; i < pts.size(); ++i) h[i] = pts[i].x;
  }
};

}  // namespace

TEST_CASE("size check: finite positive sizes pass through unchanged") {
  const FieldPtr f = checked_size_field(std::make_shared<XField>(), 3, "MathEval");
  const std::vector<Vec3> pts = {{0.5, 0, 0}, {1e22, 0, 0}, {1e-300, 0, 0}};
  std::vector<double> h(3);
  f->eval(pts, h);
  CHECK(h == std::vector<double>{0.5, 1e22, 1e-300});
  f->eval_on(EntityRef{2, 1}, pts, h);
  CHECK(h[0] == 0.5);
  CHECK(checked_size_field(nullptr, 1, "Box") == nullptr);
}

TEST_CASE("size check: the first bad size of a batch is a typed error with field id and point") {
  const FieldPtr f = checked_size_field(std::make_shared<XField>(), 3, "MathEval");
  for (const double bad : {0.0, -1.0, std::nan(""), double(INFINITY), -double(INFINITY)}) {
    const std::vector<Vec3> pts = {{1, 0, 0}, {bad, 2, 3}, {-5, 0, 0}};
    std::vector<double> h(3);
    try {
      f->eval(pts, h);
      FAIL("no error for ", bad);
    } catch (const FieldError& e) {
      CHECK(e.code() == FieldErrc::BadValue);
      CHECK(e.field_id == 3);
      REQUIRE(e.point.has_value());
      CHECK(e.point->y == 2);   // the first bad point, not the later -5
      CHECK(std::string(e.what()).find("Field[3] (MathEval) gives the mesh size") != std::string::npos);
    }
  }
}
