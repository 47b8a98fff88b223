// mesh/transfinite_curve: Gmsh's Progression, Bump and Beta laws against hand values, the
// reversed laws, and the law placed on a model curve.
#include "mesh/transfinite_curve.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "geo/model.h"

namespace transfinite_curve_testing {

sm::TransfiniteCurveSpec law(int nodes, sm::TransfiniteLaw l, double coef, bool reversed = false) {
  sm::TransfiniteCurveSpec s;
  s.nodes = nodes, s.law = l, s.coef = coef, s.reversed = reversed;
  return s;
}

}  // namespace transfinite_curve_testing

TEST_CASE("transfinite curve: Progression 1.2 on 5 nodes is the geometric series") {
  using namespace transfinite_curve_testing;
  // Steps a, 1.2a, 1.44a, 1.728a summing to 1: (1.2^k - 1) / (1.2^4 - 1).
  const std::vector<double> want = {0.0, 0.1862891207153502, 0.4098360655737705, 0.6780923994038747, 1.0};
  const std::vector<double> x = sm::transfinite_abscissae(law(5, sm::TransfiniteLaw::Progression, 1.2));
  REQUIRE(x.size() == want.size());
  for (std::size_t k = 0; k < x.size(); ++k) CHECK(x[k] == doctest::Approx(want[k]).epsilon(1e-12));
  // A negative tag: the same steps from the other end.
  const std::vector<double> r = sm::transfinite_abscissae(law(5, sm::TransfiniteLaw::Progression, 1.2, true));
  for (std::size_t k = 0; k < r.size(); ++k)
    CHECK(r[k] == doctest::Approx(1.0 - want[want.size() - 1 - k]).epsilon(1e-12));
}

TEST_CASE("transfinite curve: equal spacing for coefficient 1, 0 and Beta below 1") {
  using namespace transfinite_curve_testing;
  for (const auto& s : {law(11, sm::TransfiniteLaw::Progression, 1.0), law(11, sm::TransfiniteLaw::Bump, 1.0),
                        law(11, sm::TransfiniteLaw::Beta, 0.5), law(11, sm::TransfiniteLaw::Progression, 0.0)}) {
    const std::vector<double> x = sm::transfinite_abscissae(s);
    REQUIRE(x.size() == 11);
    for (int k = 0; k < 11; ++k) CHECK(x[k] == doctest::Approx(k / 10.0).epsilon(1e-12));
  }
  // Fewer than 2 nodes is 2, as in Gmsh.
  CHECK(sm::transfinite_abscissae(law(0, sm::TransfiniteLaw::Progression, 1.0)).size() == 2);
}

TEST_CASE("transfinite curve: Bump is symmetric, its end spacing the coefficient times the middle one") {
  using namespace transfinite_curve_testing;
  for (double c : {0.25, 4.0}) {
    const std::vector<double> x = sm::transfinite_abscissae(law(41, sm::TransfiniteLaw::Bump, c));
    REQUIRE(x.size() == 41);
    for (std::size_t k = 0; k < x.size(); ++k) CHECK(x[k] + x[x.size() - 1 - k] == doctest::Approx(1.0).epsilon(1e-9));
    const double end = x[1] - x[0], middle = x[21] - x[20];
    CHECK(end / middle == doctest::Approx(c).epsilon(0.1));   // the discrete spacing of the continuous sizes
  }
}

TEST_CASE("transfinite curve: Beta 2 on 6 nodes inverts its closed-form primitive") {
  using namespace transfinite_curve_testing;
  // F(t) = 1 + ln((c - 1 + t) / (1 + c - t)) / ln((1 + c) / (c - 1)) at k / 5.
  const std::vector<double> want = {0.0, 0.17363154409245488, 0.3637066976158501, 0.5674929709256274,
                                    0.7811572746487718, 1.0};
  const std::vector<double> x = sm::transfinite_abscissae(law(6, sm::TransfiniteLaw::Beta, 2.0));
  REQUIRE(x.size() == 6);
  for (std::size_t k = 0; k < x.size(); ++k) CHECK(x[k] == doctest::Approx(want[k]).epsilon(1e-9));
  const std::vector<double> r = sm::transfinite_abscissae(law(6, sm::TransfiniteLaw::Beta, 2.0, true));
  for (std::size_t k = 0; k < r.size(); ++k) CHECK(r[k] == doctest::Approx(1.0 - want[5 - k]).epsilon(1e-9));
}

TEST_CASE("transfinite curve: the law on a model Line and on a quarter circle") {
  using namespace transfinite_curve_testing;
  sm::geo::Model m;
  REQUIRE(m.add_point(1, {0, 0, 0}).ok());
  REQUIRE(m.add_point(2, {3, 4, 0}).ok());
  REQUIRE(m.add_point(3, {5, 0, 0}).ok());
  REQUIRE(m.add_curve(1, sm::geo::CurveKind::Line, {1, 2}).ok());
  REQUIRE(m.add_curve(2, sm::geo::CurveKind::Circle, {3, 1, 2}).ok());
  const sm::TransfiniteCurveSpec s = law(5, sm::TransfiniteLaw::Progression, 1.2);
  const std::vector<double> a = sm::transfinite_abscissae(s);
  for (int c : {1, 2}) {
    const std::vector<double> t = sm::transfinite_parameters(*m.curve(c)->shape, s);
    REQUIRE(t.size() == 5);
    // Both are parametrised at constant speed: the parameters are the abscissae.
    for (std::size_t k = 0; k < t.size(); ++k) CHECK(t[k] == doctest::Approx(a[k]).epsilon(1e-9));
  }
}
