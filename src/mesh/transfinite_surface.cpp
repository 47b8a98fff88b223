// Transfinite filling of 3- and 4-sided faces (Gmsh 4.8.4's meshGFaceTransfinite.cpp
// semantics: side counts, the interpolation, the diagonals; see the header).
#include "mesh/transfinite_surface.h"

#include <algorithm>
#include <fmt/format.h>

namespace sm {

std::vector<std::size_t> implicit_transfinite_corners(std::span<const std::size_t> starts, std::size_t n) {
  std::vector<std::size_t> c(starts.begin(), starts.end());
  if (c.size() == 3) {
    // Sides c0 -> c1 and c2 -> c0 are the ones the 3-sided form needs equal.
    auto edges = [&](std::size_t a, std::size_t b) { return (b + n - a) % n; };
    if (edges(c[0], c[1]) != edges(c[2], c[0])) c = {c[1], c[2], c[0]};
  }
  return c;
}

TransfiniteResult fill_transfinite(const TransfiniteBoundary& b, TriangleArrangement arrangement, bool quads,
                                   int smoothing) {
  TransfiniteResult r;
  const std::size_t n = b.coords.size();
  const std::size_t nc = b.corners.size();
  if (nc != 3 && nc != 4) {
    r.error = fmt::format("is transfinite but has {} corner{} (give 3 or 4)", nc, nc == 1 ? "" : "s");
    r.fault = TransfiniteFault::CornerCount;
    r.numbers = {static_cast<int>(nc)};
    return r;
  }
  for (std::size_t c : b.corners)
    if (c >= n) {
      r.error = "a transfinite corner is not on the boundary";
      r.fault = TransfiniteFault::CornerOffBoundary;
      return r;
    }
  // m[k]: the chain position of the k-th node going round from corner 0 towards corner 1.
  std::vector<std::size_t> m(n);
  for (std::size_t k = 0; k < n; ++k) m[k] = (b.corners[0] + k) % n;
  auto is_corner = [&](std::size_t pos, std::size_t from) {
    for (std::size_t i = from; i < nc; ++i)
      if (b.corners[i] == pos) return true;
    return false;
  };
  bool reversed = false;
  for (std::size_t k = 1; k < n; ++k)
    if (is_corner(m[k], 1)) {
      reversed = m[k] != b.corners[1];
      break;
    }
  if (reversed) std::reverse(m.begin() + 1, m.end());
  std::vector<std::size_t> N;
  for (std::size_t k = 0; k < n; ++k)
    if (is_corner(m[k], 0)) N.push_back(k);
  if (N.size() != nc) {
    r.error = "transfinite parameters are incoherent (a corner is listed twice)";
    r.fault = TransfiniteFault::CornerTwice;
    return r;
  }
  const int L = static_cast<int>(N[1] - N[0]), H = static_cast<int>(N[2] - N[1]);
  if (nc == 4) {
    const int Lb = static_cast<int>(N[3] - N[2]), Hb = static_cast<int>(n - N[3]);
    if (Lb != L || Hb != H) {
      r.error = fmt::format("cannot be meshed using the transfinite algo (divisions {} != {} or {} != {})", Lb, L, Hb, H);
      r.fault = TransfiniteFault::SidesUnequal4;
      r.numbers = {Lb, L, Hb, H};
      return r;
    }
  } else {
    const int Lb = static_cast<int>(n - N[2]);
    if (Lb != L) {
      r.error = fmt::format("cannot be meshed using the transfinite algo (divisions {} != {})", L, Lb);
      r.fault = TransfiniteFault::SidesUnequal3;
      r.numbers = {L, Lb};
      return r;
    }
  }
  if (L < 1 || H < 1) {
    r.error = "a transfinite side has no edge";
    r.fault = TransfiniteFault::EmptySide;
    return r;
  }
  r.L = L, r.H = H;
  auto X = [&](std::size_t k) { return b.coords[m[k % n]]; };
  auto P = [&](std::size_t k) { return b.xyz[m[k % n]]; };
  // Relative lengths along the first side (u) and the second (v), in space.
  std::vector<double> len_i(static_cast<std::size_t>(L) + 1, 0.0), len_j(static_cast<std::size_t>(H) + 1, 0.0);
  for (int i = 0; i < L; ++i) len_i[i + 1] = len_i[i] + norm(P(i + 1) - P(i));
  for (int j = 0; j < H; ++j) len_j[j + 1] = len_j[j] + norm(P(L + j + 1) - P(L + j));
  // tab[i][j]: element index (chain position, or n + interior index).
  const std::size_t W = static_cast<std::size_t>(H) + 1;
  std::vector<std::uint32_t> tab((static_cast<std::size_t>(L) + 1) * W);
  auto at = [&](int i, int j) -> std::uint32_t& { return tab[static_cast<std::size_t>(i) * W + static_cast<std::size_t>(j)]; };
  auto pos = [&](std::size_t k) { return static_cast<std::uint32_t>(m[k % n]); };
  at(0, 0) = pos(0), at(L, 0) = pos(L), at(L, H) = pos(L + H);
  at(0, H) = nc == 4 ? pos(2 * L + H) : pos(0);
  for (int i = 1; i < L; ++i) at(i, 0) = pos(i), at(i, H) = pos(2 * L + H - i);
  for (int j = 1; j < H; ++j) at(L, j) = pos(L + j), at(0, j) = nc == 4 ? pos(2 * L + 2 * H - j) : pos(0);
  const Vec3 s1 = X(N[0]), s2 = X(N[1]), s3 = X(N[2]), s4 = nc == 4 ? X(N[3]) : Vec3{};
  const double Li = len_i[L] > 0 ? len_i[L] : 1.0, Lj = len_j[H] > 0 ? len_j[H] : 1.0;
  for (int i = 1; i < L; ++i) {
    const double u = len_i[i] / Li;
    for (int j = 1; j < H; ++j) {
      const double v = len_j[j] / Lj;
      Vec3 p;
      if (nc == 4) {
        const Vec3 c1 = X(N[0] + i), c2 = X(N[1] + j), c3 = X(N[3] - i), c4 = X(N[3] + H - j);
        // Coons: (1-u) c4(v) + u c2(v) + (1-v) c1(u) + v c3(u) minus the bilinear corners.
        p = (1 - u) * c4 + u * c2 + (1 - v) * c1 + v * c3 -
            ((1 - u) * (1 - v) * s1 + u * (1 - v) * s2 + u * v * s3 + (1 - u) * v * s4);
      } else {
        const Vec3 c1 = X(N[0] + i), c2 = X(N[1] + j), c3 = X(N[2] + N[1] - i);
        // The 3-sided form: corner s1 = s4 is the degenerate side.
        p = u * c2 + (1 - v) * c1 + v * c3 - (u * (1 - v) * s2 + u * v * s3);
      }
      at(i, j) = static_cast<std::uint32_t>(n + r.interior.size());
      r.interior.push_back(p);
    }
  }
  if (nc == 4 && smoothing > 0 && L > 1 && H > 1) {
    // Elliptic smoothing (Winslow-type: the grid's alpha, beta, gamma weights), interior only.
    auto coord = [&](int i, int j) -> Vec3 {
      const std::uint32_t k = at(i, j);
      return k < n ? b.coords[k] : r.interior[k - n];
    };
    for (int it = 0; it < smoothing; ++it)
      for (int i = 1; i < L; ++i)
        for (int j = 1; j < H; ++j) {
          const Vec3 di = coord(i + 1, j) - coord(i - 1, j), dj = coord(i, j + 1) - coord(i, j - 1);
          const double alpha = 0.25 * dot(dj, dj), gamma = 0.25 * dot(di, di), beta = 0.0625 * dot(di, dj);
          if (!(alpha + gamma > 0)) continue;
          const Vec3 cross_term = coord(i + 1, j + 1) - coord(i - 1, j + 1) - coord(i + 1, j - 1) + coord(i - 1, j - 1);
          r.interior[at(i, j) - n] = 0.5 *
                                     (alpha * (coord(i + 1, j) + coord(i - 1, j)) +
                                      gamma * (coord(i, j + 1) + coord(i, j - 1)) - 2.0 * beta * cross_term) /
                                     (alpha + gamma);
        }
  }
  // Elements oriented as the grid (i along side 1, j along side 2) turns, which is the
  // chain's turning unless the corners run against it.
  auto tri = [&](std::uint32_t a, std::uint32_t c, std::uint32_t d) {
    r.triangles.push_back(reversed ? std::array<std::uint32_t, 3>{a, d, c} : std::array<std::uint32_t, 3>{a, c, d});
  };
  auto cell = [&](int i, int j) {
    const std::uint32_t v1 = at(i, j), v2 = at(i + 1, j), v3 = at(i + 1, j + 1), v4 = at(i, j + 1);
    if (quads) {
      r.quads.push_back(reversed ? std::array<std::uint32_t, 4>{v1, v4, v3, v2} : std::array<std::uint32_t, 4>{v1, v2, v3, v4});
      return;
    }
    const bool odd = (i + j) % 2 == 1;
    const bool right = arrangement == TriangleArrangement::Right ||
                       (arrangement == TriangleArrangement::AlternateRight && odd) ||
                       (arrangement == TriangleArrangement::AlternateLeft && !odd);
    if (right) {
      tri(v1, v2, v3), tri(v3, v4, v1);
    } else {
      tri(v1, v2, v4), tri(v4, v2, v3);
    }
  };
  if (nc == 4) {
    for (int i = 0; i < L; ++i)
      for (int j = 0; j < H; ++j) cell(i, j);
  } else {
    for (int j = 0; j < H; ++j) tri(at(0, 0), at(1, j), at(1, j + 1));
    for (int i = 1; i < L; ++i)
      for (int j = 0; j < H; ++j) cell(i, j);
  }
  return r;
}

}  // namespace sm
