// Predicates against an exact oracle: every double is m * 2^e, so after
// scaling by the smallest exponent the determinants are big-integer sums.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "exact/predicates.h"

using namespace sm;

namespace {

// Signed big integer, base 2^32, just enough for the oracle.
struct Big {
  bool neg = false;
  std::vector<std::uint32_t> mag;  // little endian, no leading zeros

  void trim() {
    while (!mag.empty() && mag.back() == 0) mag.pop_back();
    if (mag.empty()) neg = false;
  }
  static int cmp_mag(const Big& a, const Big& b) {
    if (a.mag.size() != b.mag.size()) return a.mag.size() < b.mag.size() ? -1 : 1;
    for (std::size_t i = a.mag.size(); i-- > 0;)
      if (a.mag[i] != b.mag[i]) return a.mag[i] < b.mag[i] ? -1 : 1;
    return 0;
  }
  static Big add_mag(const Big& a, const Big& b) {
    Big r;
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < std::max(a.mag.size(), b.mag.size()) || carry; ++i) {
      std::uint64_t s = carry;
      if (i < a.mag.size()) s += a.mag[i];
      if (i < b.mag.size()) s += b.mag[i];
      r.mag.push_back(static_cast<std::uint32_t>(s));
      carry = s >> 32;
    }
    return r;
  }
  static Big sub_mag(const Big& a, const Big& b) {  // |a| >= |b|
    Big r;
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < a.mag.size(); ++i) {
      std::int64_t s = static_cast<std::int64_t>(a.mag[i]) - borrow - (i < b.mag.size() ? b.mag[i] : 0);
      borrow = s < 0;
      if (s < 0) s += (std::int64_t{1} << 32);
      r.mag.push_back(static_cast<std::uint32_t>(s));
    }
    r.trim();
    return r;
  }
  friend Big operator+(const Big& a, const Big& b) {
    Big r;
    if (a.neg == b.neg) {
      r = add_mag(a, b);
      r.neg = a.neg;
    } else if (cmp_mag(a, b) >= 0) {
      r = sub_mag(a, b);
      r.neg = a.neg;
    } else {
      r = sub_mag(b, a);
      r.neg = b.neg;
    }
    r.trim();
    return r;
  }
  friend Big operator-(const Big& a, const Big& b) {
    Big nb = b;
    if (!nb.mag.empty()) nb.neg = !nb.neg;
    return a + nb;
  }
  friend Big operator*(const Big& a, const Big& b) {
    Big r;
    r.mag.assign(a.mag.size() + b.mag.size() + 1, 0);
    for (std::size_t i = 0; i < a.mag.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < b.mag.size() || carry; ++j) {
        std::uint64_t cur = r.mag[i + j] + carry + (j < b.mag.size() ? std::uint64_t{a.mag[i]} * b.mag[j] : 0);
        r.mag[i + j] = static_cast<std::uint32_t>(cur);
        carry = cur >> 32;
      }
    }
    r.neg = a.neg != b.neg;
    r.trim();
    return r;
  }
  Sign sign() const { return mag.empty() ? Sign::Zero : (neg ? Sign::Negative : Sign::Positive); }
};

// Exact value of each double as an integer times 2^min_exp.
std::vector<Big> to_big(const std::vector<double>& v) {
  int min_exp = 100000;
  for (double x : v)
    if (x != 0) {
      int e;
      std::frexp(x, &e);
      min_exp = std::min(min_exp, e - 53);
    }
  std::vector<Big> out;
  for (double x : v) {
    Big b;
    if (x != 0) {
      int e;
      const double m = std::frexp(std::fabs(x), &e);
      auto mant = static_cast<std::uint64_t>(std::ldexp(m, 53));  // exact
      int shift = e - 53 - min_exp;
      b.mag = {static_cast<std::uint32_t>(mant), static_cast<std::uint32_t>(mant >> 32)};
      b.trim();
      Big two;
      two.mag = {2};
      while (shift-- > 0) b = b * two;
      b.neg = x < 0;
    }
    out.push_back(b);
  }
  return out;
}

Sign oracle_orient2d(Vec2 a, Vec2 b, Vec2 c) {
  auto v = to_big({a.x, a.y, b.x, b.y, c.x, c.y});
  return ((v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4])).sign();
}

Sign oracle_incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  auto v = to_big({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y});
  const Big adx = v[0] - v[6], ady = v[1] - v[7], bdx = v[2] - v[6], bdy = v[3] - v[7];
  const Big cdx = v[4] - v[6], cdy = v[5] - v[7];
  const Big al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
  return (al * (bdx * cdy - cdx * bdy) + bl * (cdx * ady - adx * cdy) + cl * (adx * bdy - bdx * ady)).sign();
}

Sign oracle_orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  auto v = to_big({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z});
  const Big adx = v[0] - v[9], ady = v[1] - v[10], adz = v[2] - v[11];
  const Big bdx = v[3] - v[9], bdy = v[4] - v[10], bdz = v[5] - v[11];
  const Big cdx = v[6] - v[9], cdy = v[7] - v[10], cdz = v[8] - v[11];
  return (adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) + cdz * (adx * bdy - bdx * ady)).sign();
}

}  // namespace

TEST_CASE("predicates: oracle sanity") {
  CHECK(oracle_orient2d({0, 0}, {1, 0}, {0, 1}) == Sign::Positive);
  CHECK(oracle_orient2d({0, 0}, {0, 1}, {1, 0}) == Sign::Negative);
  CHECK(oracle_incircle({0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}) == Sign::Positive);
  CHECK(oracle_incircle({0, 0}, {1, 0}, {0, 1}, {1, 1}) == Sign::Zero);
}

TEST_CASE("predicates: simple signs") {
  CHECK(orient2d({0, 0}, {1, 0}, {0, 1}) == Sign::Positive);
  CHECK(orient2d({0, 0}, {0, 1}, {1, 0}) == Sign::Negative);
  CHECK(orient2d({0, 0}, {1, 1}, {2, 2}) == Sign::Zero);
  CHECK(incircle({0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}) == Sign::Positive);
  CHECK(incircle({0, 0}, {1, 0}, {0, 1}, {2, 2}) == Sign::Negative);
  CHECK(incircle({0, 0}, {1, 0}, {0, 1}, {1, 1}) == Sign::Zero);
  CHECK(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}) == Sign::Positive);
  CHECK(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == Sign::Negative);
}

TEST_CASE("predicates: points on a line at 1e-16 offsets (orient2d)") {
  // The classic grid of Kettner et al.: p = (0.5 + i u, 0.5 + j u) against the
  // line through (12,12) and (24,24); naive evaluation gets many signs wrong.
  PredicateStats st;
  const double u = std::ldexp(1.0, -53);
  int mismatches_naive = 0;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const Vec2 p{0.5 + i * u, 0.5 + j * u}, q{12, 12}, r{24, 24};
      const Sign want = oracle_orient2d(p, q, r);
      REQUIRE(orient2d(p, q, r, &st) == want);
      CHECK(orient2d(q, r, p) == want);
      CHECK(orient2d(r, q, p) == -want);
      const double naive = (p.x - r.x) * (q.y - r.y) - (p.y - r.y) * (q.x - r.x);
      if (detail::sign_of(naive) != want) ++mismatches_naive;
    }
  CHECK(mismatches_naive > 0);        // the test really is near-degenerate
  CHECK(st.orient2d_exact > 0);       // and the filter sent those to the exact stage
  CHECK(st.orient2d_calls == 64 * 64);
}

TEST_CASE("predicates: Kahan-style nearly collinear triples and random perturbations") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 3000; ++k) {
    const Vec2 a{U(rng), U(rng)}, b{U(rng), U(rng)};
    const double t = U(rng) * 3;
    Vec2 c = a + t * (b - a);  // rounded: within an ulp or so of the line
    const int ulps = static_cast<int>(rng() % 5) - 2;
    for (int s = 0; s < std::abs(ulps); ++s) c.x = std::nextafter(c.x, ulps > 0 ? 10.0 : -10.0);
    REQUIRE(orient2d(a, b, c) == oracle_orient2d(a, b, c));
    REQUIRE(orient2d(c, a, b) == oracle_orient2d(c, a, b));
  }
  // Kahan's triangle: nearly degenerate with huge dynamic range.
  const Vec2 a{1e15 + 1, 1e15}, b{1e15, 1e15 - 1}, c{-1e15, -1e15 - 1};
  CHECK(orient2d(a, b, c) == oracle_orient2d(a, b, c));
}

TEST_CASE("predicates: cocircular grids (incircle)") {
  // Integer grid points on circles x^2 + y^2 = 25, 65, 325: exactly cocircular,
  // then each shifted by one ulp to either side.
  PredicateStats st;
  std::vector<Vec2> pts;
  for (int x = -18; x <= 18; ++x)
    for (int y = -18; y <= 18; ++y)
      if (x * x + y * y == 325) pts.push_back({x * 0.1, y * 0.1});  // not exactly representable
  REQUIRE(pts.size() >= 8);
  int zero = 0;
  for (std::size_t i = 0; i + 3 < pts.size(); ++i) {
    const Vec2 a = pts[i], b = pts[i + 1], c = pts[i + 2], d = pts[i + 3];
    const Sign want = oracle_incircle(a, b, c, d);
    REQUIRE(incircle(a, b, c, d, &st) == want);
    for (int dir : {-1, 1}) {
      Vec2 e = d;
      e.y = std::nextafter(e.y, dir * 100.0);
      REQUIRE(incircle(a, b, c, e) == oracle_incircle(a, b, c, e));
    }
  }
  // Exactly representable cocircular points: must be exactly Zero.
  const Vec2 g[] = {{3, 4}, {-4, 3}, {-3, -4}, {4, -3}, {5, 0}, {0, 5}, {-5, 0}, {0, -5}};
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k)
        for (int l = 0; l < 8; ++l) {
          if (i == j || i == k || i == l || j == k || j == l || k == l) continue;
          const Sign got = incircle(g[i], g[j], g[k], g[l], &st);
          CHECK(got == Sign::Zero);
          zero += got == Sign::Zero;
        }
  CHECK(zero == 8 * 7 * 6 * 5);
  CHECK(st.incircle_exact > 0);
}

TEST_CASE("predicates: random near-degenerate incircle and orient3d against the oracle") {
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    // d on (or within a few ulps of) the circle through a, b, c.
    const double r = 0.5 + 0.5 * std::fabs(U(rng));
    const Vec2 o{U(rng), U(rng)};
    auto on = [&](double th) { return Vec2{o.x + r * std::cos(th), o.y + r * std::sin(th)}; };
    const Vec2 a = on(0.3 + U(rng)), b = on(2.4 + U(rng)), c = on(4.5 + U(rng)), d = on(U(rng) * 7);
    REQUIRE(incircle(a, b, c, d) == oracle_incircle(a, b, c, d));
    const Vec3 p{U(rng), U(rng), U(rng)}, q{U(rng), U(rng), U(rng)}, w{U(rng), U(rng), U(rng)};
    const double s = U(rng), t = U(rng);
    const Vec3 z = p + s * (q - p) + t * (w - p);  // nearly coplanar
    REQUIRE(orient3d(p, q, w, z) == oracle_orient3d(p, q, w, z));
  }
}

TEST_CASE("predicates: huge and tiny coordinates") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> U(-1, 1);
  for (double scale : {1e-300, 1e-200, 1e-150, 1e-20, 1e20, 1e150, 1e200, 1e300}) {
    for (int k = 0; k < 300; ++k) {
      const Vec2 a{U(rng) * scale, U(rng) * scale}, b{U(rng) * scale, U(rng) * scale};
      Vec2 c = a + 0.37 * (b - a);
      if (k % 2) c.y = std::nextafter(c.y, 0.0);
      REQUIRE(orient2d(a, b, c) == oracle_orient2d(a, b, c));
      const Vec2 d{U(rng) * scale, U(rng) * scale};
      const Sign o = oracle_orient2d(a, b, d);
      if (o == Sign::Positive) {
        const Vec2 e{(a.x + b.x) / 2, (a.y + d.y) / 2};
        REQUIRE(incircle(a, b, d, e) == oracle_incircle(a, b, d, e));
        REQUIRE(incircle(a, b, d, c) == oracle_incircle(a, b, d, c));
      }
    }
  }
  // Coincident points give Zero at any scale.
  CHECK(orient2d({1e-310, 0}, {1e-310, 0}, {5, 5}) == Sign::Zero);
  CHECK(orient2d({0, 0}, {0, 0}, {0, 0}) == Sign::Zero);
}
