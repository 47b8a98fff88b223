// Transfinite node distributions (Gmsh 4.8.4 meshGEdge.cpp's laws; see the header).
#include "mesh/transfinite_curve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace sm {
namespace {

bool uniform(const TransfiniteCurveSpec& s) {
  return s.coef <= 0 || s.coef == 1.0 || (s.law == TransfiniteLaw::Beta && s.coef < 1.0);
}

double progression_ratio(const TransfiniteCurveSpec& s) { return s.reversed ? 1.0 / s.coef : s.coef; }

// 5-point Gauss-Legendre on [0, 1].
constexpr std::array<double, 5> kGaussX = {0.04691007703066800, 0.23076534494715845, 0.5, 0.76923465505284155,
                                           0.95308992296933200};
constexpr std::array<double, 5> kGaussW = {0.11846344252809454, 0.23931433524968324, 0.28444444444444444,
                                           0.23931433524968324, 0.11846344252809454};

double gauss(const std::function<double(double)>& f, double a, double b) {
  double s = 0;
  for (std::size_t k = 0; k < kGaussX.size(); ++k) s += kGaussW[k] * f(a + kGaussX[k] * (b - a));
  return s * (b - a);
}

// Parameters of n nodes at equal shares of the integral of `density` over [0, 1], with
// the grid's `breaks` (sorted, 0 and 1 included) as the integration cells.
std::vector<double> invert(const std::function<double(double)>& density, const std::vector<double>& breaks, int n) {
  std::vector<double> acc(breaks.size(), 0.0);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) acc[i + 1] = acc[i] + gauss(density, breaks[i], breaks[i + 1]);
  const double total = acc.back();
  std::vector<double> out(static_cast<std::size_t>(n));
  out.front() = 0;
  out.back() = 1;
  std::size_t j = 0;
  for (int k = 1; k + 1 < n; ++k) {
    const double target = total * k / (n - 1);
    while (j + 2 < breaks.size() && acc[j + 1] < target) ++j;
    double lo = breaks[j], hi = breaks[j + 1];
    const double need = target - acc[j];
    for (int it = 0; it < 60 && hi - lo > 1e-16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (gauss(density, breaks[j], mid) < need ? lo : hi) = mid;
    }
    out[static_cast<std::size_t>(k)] = std::clamp(0.5 * (lo + hi), out[static_cast<std::size_t>(k) - 1], 1.0);
  }
  return out;
}

// The cells: a uniform grid, plus a progression's step ends (the density jumps there).
std::vector<double> cells(const TransfiniteCurveSpec& s) {
  const int m = std::max(256, 16 * s.nodes);
  std::vector<double> b;
  b.reserve(static_cast<std::size_t>(m + s.nodes + 1));
  for (int i = 0; i <= m; ++i) b.push_back(static_cast<double>(i) / m);
  if (s.law == TransfiniteLaw::Progression && !uniform(s)) {
    const double r = progression_ratio(s);
    const double total = std::pow(r, s.nodes - 1.0) - 1.0;
    for (int k = 1; k + 1 < s.nodes; ++k) b.push_back((std::pow(r, k) - 1.0) / total);
  }
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

}  // namespace

double transfinite_density(const TransfiniteCurveSpec& s, double t, double speed, double length) {
  if (uniform(s)) return speed / length;
  const double n = s.nodes;
  switch (s.law) {
    case TransfiniteLaw::Progression: {
      const double r = progression_ratio(s);
      const double a = length * (r - 1.0) / (std::pow(r, n - 1.0) - 1.0);
      // The step holding t; clamped so that t = 1 stays in the last one.
      const double i = std::clamp(std::floor(std::log(t * length / a * (r - 1.0) + 1.0) / std::log(r)), 0.0, n - 2.0);
      return speed / (a * std::pow(r, i));
    }
    case TransfiniteLaw::Bump: {
      const double c = s.coef;
      const double a =
          c > 1.0 ? -4.0 * std::sqrt(c - 1.0) * std::atan2(1.0, std::sqrt(c - 1.0)) / (n * length)
                  : 2.0 * std::sqrt(1.0 - c) *
                        std::log(std::abs((1.0 + 1.0 / std::sqrt(1.0 - c)) / (1.0 - 1.0 / std::sqrt(1.0 - c)))) /
                        (n * length);
      const double b = -a * length * length / (4.0 * (c - 1.0));
      const double x = t * length - 0.5 * length;
      return speed / (-a * x * x + b);
    }
    case TransfiniteLaw::Beta: {
      const double c = s.coef;
      const double u = s.reversed ? 1.0 - t : t;
      return 2.0 * c / ((1.0 + c - u) * (c - 1.0 + u) * std::log((1.0 + c) / (c - 1.0)));
    }
  }
  return speed / length;
}

std::vector<double> transfinite_parameters(const geo::Curve& c, const TransfiniteCurveSpec& spec) {
  TransfiniteCurveSpec s = spec;
  s.nodes = std::max(s.nodes, 2);
  const std::vector<double> b = cells(s);
  auto speed = [&](double t) { return norm(c.eval(t).d1); };
  double length = 0;
  for (std::size_t i = 0; i + 1 < b.size(); ++i) length += gauss(speed, b[i], b[i + 1]);
  if (!(length > 0)) {
    std::vector<double> out(static_cast<std::size_t>(s.nodes));
    for (int k = 0; k < s.nodes; ++k) out[static_cast<std::size_t>(k)] = static_cast<double>(k) / (s.nodes - 1);
    return out;
  }
  return invert([&](double t) { return transfinite_density(s, t, speed(t), length); }, b, s.nodes);
}

std::vector<double> transfinite_abscissae(const TransfiniteCurveSpec& spec) {
  TransfiniteCurveSpec s = spec;
  s.nodes = std::max(s.nodes, 2);
  return invert([&](double t) { return transfinite_density(s, t, 1.0, 1.0); }, cells(s), s.nodes);
}

}  // namespace sm
