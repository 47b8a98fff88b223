// Exact stage of the predicates: floating-point expansion arithmetic
// (Priest 1991, Shewchuk 1997). An expansion is a sum of non-overlapping
// doubles stored smallest first; sums and products of expansions are exact.
#include "exact/predicates.h"

#include <algorithm>
#include <cmath>

namespace sm::detail {
namespace {

// a + b = x + y exactly, |y| <= ulp(x)/2 (Knuth's branch-free two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// a * b = x + y exactly; the fused multiply-add yields the rounding error.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// h = e + f (zero components removed); returns the length of h. h must not
// alias e or f and has room for elen + flen components.
int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) {
  if (elen == 0) {
    std::copy(f, f + flen, h);
    return flen;
  }
  if (flen == 0) {
    std::copy(e, e + elen, h);
    return elen;
  }
  // Merge by magnitude, then accumulate with two-sum (Shewchuk's
  // linear-expansion-sum with zero elimination, written out plainly).
  double q, qnew, hh;
  int ei = 0, fi = 0, hi = 0;
  auto take = [&]() {
    if (fi >= flen || (ei < elen && std::fabs(e[ei]) < std::fabs(f[fi]))) return e[ei++];
    return f[fi++];
  };
  q = take();
  while (ei < elen || fi < flen) {
    const double next = take();
    two_sum(q, next, qnew, hh);
    q = qnew;
    if (hh != 0.0) h[hi++] = hh;
  }
  if (q != 0.0 || hi == 0) h[hi++] = q;
  return hi;
}

// h = e * b (zero components removed); h has room for 2 * elen components.
int scale_expansion(int elen, const double* e, double b, double* h) {
  double q, hh, p1, p0, sum;
  int hi = 0;
  two_product(e[0], b, q, hh);
  if (hh != 0.0) h[hi++] = hh;
  for (int i = 1; i < elen; ++i) {
    two_product(e[i], b, p1, p0);
    two_sum(q, p0, sum, hh);
    if (hh != 0.0) h[hi++] = hh;
    two_sum(p1, sum, q, hh);
    if (hh != 0.0) h[hi++] = hh;
  }
  if (q != 0.0 || hi == 0) h[hi++] = q;
  return hi;
}

// A fixed-capacity expansion on the stack; the exact stage never allocates.
template <int N>
struct Exp {
  double c[N];
  int n = 0;
  Sign sign() const { return n == 0 ? Sign::Zero : sign_of(c[n - 1]); }
};

template <int N>
Exp<N> diff(double a, double b) {
  Exp<N> r;
  double x, y;
  two_sum(a, -b, x, y);
  if (y != 0.0) r.c[r.n++] = y;
  if (x != 0.0 || r.n == 0) r.c[r.n++] = x;
  return r;
}

template <int N, int A, int B>
Exp<N> add(const Exp<A>& a, const Exp<B>& b) {
  static_assert(N >= A + B);
  Exp<N> r;
  r.n = expansion_sum(a.n, a.c, b.n, b.c, r.c);
  return r;
}

template <int N, int A>
Exp<N> neg(const Exp<A>& a) {
  Exp<N> r;
  r.n = a.n;
  for (int i = 0; i < a.n; ++i) r.c[i] = -a.c[i];
  return r;
}

template <int N, int A, int B>
Exp<N> sub(const Exp<A>& a, const Exp<B>& b) {
  return add<N>(a, neg<B>(b));
}

// Product of two expansions: sum over the components of b of a * b_i.
template <int N, int A, int B>
Exp<N> mul(const Exp<A>& a, const Exp<B>& b) {
  static_assert(N >= 2 * A * B);
  Exp<N> acc, tmp;
  double part[2 * A];
  for (int i = 0; i < b.n; ++i) {
    const int pn = scale_expansion(a.n, a.c, b.c[i], part);
    tmp.n = expansion_sum(acc.n, acc.c, pn, part, tmp.c);
    acc.n = tmp.n;
    std::copy(tmp.c, tmp.c + tmp.n, acc.c);
  }
  if (acc.n == 0) acc.c[acc.n++] = 0.0;
  return acc;
}

// Power of two that brings the largest magnitude near 1: scaling every
// coordinate by it is exact and keeps the expansions clear of overflow and
// underflow (inputs spanning fewer than ~2^250 in magnitude stay exact).
double normalising_scale(std::initializer_list<double> v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  if (m == 0) return 0;
  int e;
  std::frexp(m, &e);
  return std::ldexp(1.0, -e);
}

}  // namespace

Sign orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  const double s = normalising_scale({a.x, a.y, b.x, b.y, c.x, c.y});
  if (s == 0) return Sign::Zero;
  a *= s, b *= s, c *= s;
  const auto acx = diff<2>(a.x, c.x), acy = diff<2>(a.y, c.y);
  const auto bcx = diff<2>(b.x, c.x), bcy = diff<2>(b.y, c.y);
  const auto l = mul<8>(acx, bcy);
  const auto r = mul<8>(acy, bcx);
  return sub<16>(l, r).sign();
}

Sign incircle_exact(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double s = normalising_scale({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y});
  if (s == 0) return Sign::Zero;
  a *= s, b *= s, c *= s, d *= s;
  const auto adx = diff<2>(a.x, d.x), ady = diff<2>(a.y, d.y);
  const auto bdx = diff<2>(b.x, d.x), bdy = diff<2>(b.y, d.y);
  const auto cdx = diff<2>(c.x, d.x), cdy = diff<2>(c.y, d.y);
  const auto bc = sub<16>(mul<8>(bdx, cdy), mul<8>(cdx, bdy));
  const auto ca = sub<16>(mul<8>(cdx, ady), mul<8>(adx, cdy));
  const auto ab = sub<16>(mul<8>(adx, bdy), mul<8>(bdx, ady));
  const auto alift = add<16>(mul<8>(adx, adx), mul<8>(ady, ady));
  const auto blift = add<16>(mul<8>(bdx, bdx), mul<8>(bdy, bdy));
  const auto clift = add<16>(mul<8>(cdx, cdx), mul<8>(cdy, cdy));
  const auto ta = mul<512>(alift, bc);
  const auto tb = mul<512>(blift, ca);
  const auto tc = mul<512>(clift, ab);
  return add<1536>(add<1024>(ta, tb), tc).sign();
}

Sign orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double s = normalising_scale({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z});
  if (s == 0) return Sign::Zero;
  a *= s, b *= s, c *= s, d *= s;
  const auto adx = diff<2>(a.x, d.x), ady = diff<2>(a.y, d.y), adz = diff<2>(a.z, d.z);
  const auto bdx = diff<2>(b.x, d.x), bdy = diff<2>(b.y, d.y), bdz = diff<2>(b.z, d.z);
  const auto cdx = diff<2>(c.x, d.x), cdy = diff<2>(c.y, d.y), cdz = diff<2>(c.z, d.z);
  const auto bc = sub<16>(mul<8>(bdx, cdy), mul<8>(cdx, bdy));
  const auto ca = sub<16>(mul<8>(cdx, ady), mul<8>(adx, cdy));
  const auto ab = sub<16>(mul<8>(adx, bdy), mul<8>(bdx, ady));
  const auto ta = mul<64>(bc, adz);
  const auto tb = mul<64>(ca, bdz);
  const auto tc = mul<64>(ab, cdz);
  return add<192>(add<128>(ta, tb), tc).sign();
}

}  // namespace sm::detail
