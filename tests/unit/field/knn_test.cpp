#include "field/knn.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <random>
#include <sstream>

#include <doctest/doctest.h>

#include "field/lonlat_grid.h"
#include "test_util.h"

using namespace sm;
using namespace sm::field;

TEST_CASE("knn: the k-d tree equals brute force on random points") {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> pts(3000), q(500);
  for (Vec3& p : pts) p = {u(rng), u(rng), u(rng)};
  for (Vec3& p : q) p = {1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng)};
  // Duplicates and a query exactly on a point.
  pts[10] = pts[11];
  q[0] = pts[5];
  KdTree tree(pts);
  std::vector<double> d(q.size()), bd(q.size());
  std::vector<std::uint32_t> idx(q.size()), bidx(q.size());
  tree.nearest(q, d, idx);
  nearest_brute_force(pts, q, bd, bidx);
  for (std::size_t i = 0; i < q.size(); ++i) {
    CHECK(d[i] == doctest::Approx(bd[i]).epsilon(1e-12));
    CHECK(norm(pts[idx[i]] - q[i]) == doctest::Approx(bd[i]).epsilon(1e-12));
  }
  CHECK(d[0] == 0);
  // The queries in their own order and in Morton order (each beating the answer before) agree.
  KdTree plain(pts, {10, 0, false});
  std::vector<double> pd(q.size());
  plain.nearest(q, pd);
  for (std::size_t i = 0; i < q.size(); ++i) CHECK(pd[i] == d[i]);
  // A (1+eps)-approximate tree stays within its bound.
  KdTree approx(pts, {10, 0.25f, true});
  approx.nearest(q, pd);
  for (std::size_t i = 0; i < q.size(); ++i) {
    CHECK(pd[i] >= bd[i] * (1 - 1e-12));
    CHECK(pd[i] <= bd[i] * 1.25 + 1e-12);
  }
}

TEST_CASE("knn: real coastline samples on the unit sphere (world_c) against brute force") {
  std::ifstream in(sm::field::testing::repo_data("gshhg/world_c.txt"));
  REQUIRE(in);
  std::vector<Vec3> pts;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == '>') continue;
    std::istringstream ls(line);
    double lon, lat;
    ls >> lon >> lat;
    pts.push_back(point_of(lon, lat, 1));
  }
  CHECK(pts.size() == 7899);
  KdTree tree(pts);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lon(-180, 180), z(-1, 1);
  // Dense enough that Morton groups of queries far from the coast share
  // candidate lists (the grouped path of KdTree::nearest).
  std::vector<Vec3> q(20000);
  for (Vec3& p : q) p = point_of(lon(rng), std::asin(z(rng)) * 180 / 3.141592653589793, 1);
  std::vector<double> d(q.size()), bd(q.size());
  std::vector<std::uint32_t> idx(q.size());
  tree.nearest(q, d, idx);
  nearest_brute_force(pts, q, bd);
  std::size_t bad = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (d[i] != doctest::Approx(bd[i]).epsilon(1e-12)) ++bad;
    if (norm(pts[idx[i]] - q[i]) != doctest::Approx(bd[i]).epsilon(1e-12)) ++bad;
  }
  CHECK(bad == 0);
}

TEST_CASE("knn: empty tree gives no constraint") {
  KdTree tree({});
  std::vector<Vec3> q = {{0, 0, 0}};
  std::vector<double> d(1);
  tree.nearest(q, d);
  CHECK(d[0] == 1e22);
}

TEST_CASE("knn: nearest_within agrees with brute force inside the radius, +inf beyond") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> pts(5000), q(3000);
  for (Vec3& p : pts) p = {u(rng), u(rng), 0.1 * u(rng)};
  for (Vec3& p : q) p = {2 * u(rng), 2 * u(rng), u(rng)};
  q.push_back(pts[17]);   // on a point
  const KdTree tree(pts);
  std::vector<double> d(q.size()), ref(q.size());
  std::vector<std::uint32_t> idx(q.size()), ref_idx(q.size());
  const double radius = 0.3;
  tree.nearest_within(q, std::span<const double>(&radius, 1), d, idx);
  nearest_brute_force(pts, q, ref, ref_idx);
  int near = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (ref[i] < 0.3) {
      ++near;
      CHECK(d[i] == ref[i]);
      CHECK(idx[i] == ref_idx[i]);
    } else {
      CHECK(std::isinf(d[i]));
      CHECK(idx[i] == std::numeric_limits<std::uint32_t>::max());
    }
  }
  CHECK(near > 300);
  CHECK(near < static_cast<int>(q.size()) - 300);
}

TEST_CASE("knn: nearest_below is exact up to the limit and above it beyond, on both search paths") {
  // 6000 samples; queries near the samples and far from them.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> pts(6000), q(4000);
  for (Vec3& p : pts) p = {u(rng), u(rng), 0.05 * u(rng)};
  for (Vec3& p : q) p = {2 * u(rng), 2 * u(rng), 1.5 * u(rng)};
  q.push_back(pts[40]);                          // on a point
  q.push_back(pts[41] + Vec3{0, 0, 0.8});         // at the limit below, up to rounding
  const KdTree tree(pts);
  std::vector<double> full(q.size()), below(q.size());
  tree.nearest(q, full);
  const double limit = norm(q.back() - pts[41]);
  tree.nearest_below(q, std::span<const double>(&limit, 1), below);
  int within = 0, beyond = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (full[i] <= limit) {
      ++within;
      CHECK(below[i] == full[i]);
    } else {
      ++beyond;
      CHECK(below[i] > limit);
      CHECK((below[i] == full[i] || std::isinf(below[i])));
    }
  }
  CHECK(below.back() == full.back());
  CHECK(within > 500);
  CHECK(beyond > 500);
  // Far queries stop early: most of them read +infinity, not their distance.
  int stopped = 0;
  for (double d : below) stopped += std::isinf(d) ? 1 : 0;
  CHECK(stopped > beyond / 2);
  // No limit (or none that bounds anything) is the plain search.
  const double none = std::numeric_limits<double>::infinity();
  tree.nearest_below(q, std::span<const double>(&none, 1), below);
  for (std::size_t i = 0; i < q.size(); ++i) CHECK(below[i] == full[i]);
  // One limit per query: every other query without one.
  std::vector<double> limits(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) limits[i] = i % 2 ? limit : none;
  tree.nearest_below(q, limits, below);
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (i % 2 == 0 || full[i] <= limit) {
      CHECK(below[i] == full[i]);
    } else {
      CHECK(below[i] > limit);
    }
  }
  // A non-finite query still reads NaN.
  const std::vector<Vec3> bad = {{std::nan(""), 0, 0}, pts[3]};
  std::vector<double> bd(2);
  const double half = 0.5;
  tree.nearest_below(bad, std::span<const double>(&half, 1), bd);
  CHECK(std::isnan(bd[0]));
  CHECK(bd[1] == 0);
}

// Within a batch each search is seeded by the answer before it (src/field/knn.cpp). On a
// lattice with repeated points and queries halfway between lattice points, many queries
// have several nearest points at exactly the same distance: every answer must still be
// brute force's (the smallest index among the nearest), whatever batch came before, on
// both query orders (Morton-sorted, where each answer is the next one's candidate, and as given).
TEST_CASE("knn: batches of seeded searches keep brute force's answers, ties included") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(0, 19), half(0, 1), len(1, 8);
  std::vector<Vec3> pts(6000);
  for (Vec3& p : pts) p = {double(cell(rng)), double(cell(rng)), double(cell(rng))};
  for (std::size_t i = 0; i < 200; ++i) pts[5000 + i] = pts[i];  // repeated points, later index
  std::vector<Vec3> q(3000);
  for (std::size_t i = 0; i < q.size(); ++i) {
    // On the lattice, between two, four or eight lattice points, or far outside it.
    q[i] = {cell(rng) + 0.5 * half(rng), cell(rng) + 0.5 * half(rng), cell(rng) + 0.5 * half(rng)};
    if (i % 50 == 0) q[i] = q[i] * 4.0 - Vec3{30, 30, 30};
  }
  std::vector<double> bd(q.size());
  std::vector<std::uint32_t> bidx(q.size());
  nearest_brute_force(pts, q, bd, bidx);
  std::size_t ties = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    std::size_t at_best = 0;
    for (const Vec3& p : pts) at_best += norm(p - q[i]) == bd[i];
    ties += at_best > 1;
  }
  CHECK(ties > q.size() / 2);  // the ties are there to be broken

  for (const bool sorted : {true, false}) {
    KdTree tree(pts, {32, 0, sorted});
    std::vector<double> d(8), wd(8);
    std::vector<std::uint32_t> idx(8), widx(8);
    const std::vector<double> far{25.0};  // nearest_within: covers every lattice query
    for (std::size_t first = 0; first < q.size();) {
      const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(len(rng)), q.size() - first);
      // Each batch is seeded by the batch before (random lengths: the seed comes from
      // near and from far queries), and by a far point before nearest_within.
      const std::span<const Vec3> batch(q.data() + first, n);
      tree.nearest(batch, std::span<double>(d.data(), n), std::span<std::uint32_t>(idx.data(), n));
      const Vec3 far_point = q[(first * 7919) % q.size()];
      tree.nearest(std::span<const Vec3>(&far_point, 1), std::span<double>(wd.data(), 1));
      tree.nearest_within(batch, far, std::span<double>(wd.data(), n), std::span<std::uint32_t>(widx.data(), n));
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = first + k;
        CHECK(idx[k] == bidx[i]);
        CHECK(d[k] == bd[i]);
        if (bd[i] < 25.0) {
          CHECK(widx[k] == bidx[i]);
          CHECK(wd[k] == bd[i]);
        } else {
          CHECK(widx[k] == std::numeric_limits<std::uint32_t>::max());
        }
      }
      first += n;
    }
  }
}

// The 2D refiners size about 15 close points a call (one insertion's circumcentres): such
// batches are ordered on the stack, larger ones (from 257 queries) on the heap
// (src/field/knn.cpp's kSmallBatch). On a lattice with ties, with one limit per query (some
// below the nearest distance, some above), every batch size gives brute force's distance
// within the limit and a value above it beyond.
TEST_CASE("knn: nearest_below in small and large batches keeps brute force's answers, ties included") {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> cell(0, 15), half(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> pts(3000);
  for (Vec3& p : pts) p = {double(cell(rng)), double(cell(rng)), double(cell(rng))};
  for (std::size_t i = 0; i < 100; ++i) pts[2000 + i] = pts[i];
  std::vector<Vec3> q(2000);
  std::vector<double> limit(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    // Clustered as a batch's circumcentres are: runs of 16 around one lattice cell.
    const std::size_t c = i / 16;
    const double cx = (c * 7) % 16, cy = (c * 11) % 16, cz = (c * 13) % 16;
    q[i] = {cx + 0.5 * half(rng), cy + 0.5 * half(rng), cz + 0.5 * half(rng)};
    if (i % 37 == 0) q[i] = q[i] * 3.0 - Vec3{20, 20, 20};
    limit[i] = 2.0 * u(rng);
  }
  std::vector<double> bd(q.size());
  nearest_brute_force(pts, q, bd);
  const KdTree tree(pts);
  for (const std::size_t batch : {std::size_t{1}, std::size_t{15}, std::size_t{256}, std::size_t{257}, q.size()}) {
    std::vector<double> d(q.size());
    for (std::size_t first = 0; first < q.size(); first += batch) {
      const std::size_t n = std::min(batch, q.size() - first);
      tree.nearest_below(std::span<const Vec3>(q.data() + first, n), std::span<const double>(limit.data() + first, n),
                         std::span<double>(d.data() + first, n));
    }
    int within = 0, beyond = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (bd[i] <= limit[i]) {
        ++within;
        CHECK(d[i] == bd[i]);
      } else {
        ++beyond;
        CHECK(d[i] > limit[i]);
      }
    }
    CHECK(within > 300);
    CHECK(beyond > 300);
    // The indices as well (nearest: no limit), smallest among the tied.
    std::vector<double> nd(q.size());
    std::vector<std::uint32_t> idx(q.size()), bidx(q.size());
    nearest_brute_force(pts, q, bd, bidx);
    for (std::size_t first = 0; first < q.size(); first += batch) {
      const std::size_t n = std::min(batch, q.size() - first);
      tree.nearest(std::span<const Vec3>(q.data() + first, n), std::span<double>(nd.data() + first, n),
                   std::span<std::uint32_t>(idx.data() + first, n));
    }
    for (std::size_t i = 0; i < q.size(); ++i) {
      CHECK(nd[i] == bd[i]);
      CHECK(idx[i] == bidx[i]);
    }
  }
}

// visit_within hands over every point nearer than the bound, and the bound shrinks to what
// the callback returns: with the squared distance returned, the least one seen is the
// nearest point's (ChannelWidth's searches rely on both).
TEST_CASE("knn: visit_within sees every point within the bound, and prunes by the callback's") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> pts(5000), q(300);
  for (Vec3& p : pts) p = {u(rng), u(rng), 0.1 * u(rng)};
  for (Vec3& p : q) p = {1.2 * u(rng), 1.2 * u(rng), 0.3 * u(rng)};
  const KdTree tree(pts);
  std::vector<double> bd(q.size());
  nearest_brute_force(pts, q, bd);
  const double r2 = 0.01;
  for (std::size_t i = 0; i < q.size(); ++i) {
    std::vector<std::uint32_t> seen, want;
    tree.visit_within(q[i], r2, [&](std::uint32_t j, double d2) {
      CHECK(d2 == norm2(pts[j] - q[i]));
      seen.push_back(j);
      return r2;
    });
    for (std::uint32_t j = 0; j < pts.size(); ++j)
      if (norm2(pts[j] - q[i]) < r2) want.push_back(j);
    std::sort(seen.begin(), seen.end());
    CHECK(seen == want);
    double least = std::numeric_limits<double>::infinity();
    std::size_t visits = 0;
    tree.visit_within(q[i], 4.0, [&](std::uint32_t, double d2) {
      ++visits;
      least = std::min(least, d2);
      return d2;
    });
    CHECK(std::sqrt(least) == bd[i]);
    CHECK(visits < 200);  // pruned: not the 5000 points within the first bound
  }
}

// The two searches of the tree of our own (from the root, and from the query's leaf
// upwards) give brute force's answer, ties included (of several points at the same
// distance the smallest index), whatever the candidate they start with: none, a cap that
// lets only strictly nearer points in, or a point of the set (as the batches' seeds).
TEST_CASE("knn: NearTree's search from the leaf up equals the descent and brute force, ties included") {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> cell(0, 15), half(0, 1), pick(0, 3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const bool lattice : {true, false}) {
    std::vector<Vec3> pts(4000);
    for (Vec3& p : pts)
      p = lattice ? Vec3{double(cell(rng)), double(cell(rng)), double(cell(rng))} : Vec3{u(rng), u(rng), 0.05 * u(rng)};
    for (std::size_t i = 0; i < 300; ++i) pts[3500 + i] = pts[i * 3];  // repeats with a larger index
    const NearTree tree(pts);
    std::size_t ties = 0;
    for (int n = 0; n < 4000; ++n) {
      Vec3 q = lattice ? Vec3{cell(rng) + 0.5 * half(rng), cell(rng) + 0.5 * half(rng), cell(rng) + 0.5 * half(rng)}
                       : Vec3{1.3 * u(rng), 1.3 * u(rng), 0.1 * u(rng)};
      if (n % 97 == 0) q = q * 5.0;  // far outside the points
      // Brute force: the least (squared distance, index).
      double want2 = std::numeric_limits<double>::infinity();
      std::uint32_t want = 0;
      std::size_t at_best = 0;
      for (std::uint32_t j = 0; j < pts.size(); ++j) {
        const double d2 = norm2(pts[j] - q);
        if (d2 < want2) want2 = d2, want = j, at_best = 0;
        at_best += d2 == want2;
      }
      ties += at_best > 1;
      // The start: nothing, a cap (the answer's distance or beyond), or a point as candidate.
      double start2 = std::numeric_limits<double>::infinity();
      std::uint32_t start = NearTree::kNoTie;
      const int how = pick(rng);
      if (how == 1) start2 = want2 * (1 + half(rng));
      if (how >= 2) {
        start = static_cast<std::uint32_t>(rng() % pts.size());
        start2 = norm2(pts[start] - q);
      }
      double d_down = start2, d_up = start2;
      std::uint32_t i_down = start, i_up = start;
      tree.search(q, d_down, i_down);
      tree.search_up(q, d_up, i_up);
      CHECK(d_up == d_down);
      CHECK(i_up == i_down);
      if (how == 1 && start2 == want2) {  // a cap at the answer: nothing strictly nearer
        CHECK(i_up == NearTree::kNoTie);
        CHECK(d_up == want2);
      } else {
        CHECK(d_up == want2);
        CHECK(i_up == want);
      }
    }
    if (lattice) CHECK(ties > 1000);
  }
  // A non-finite query finds nothing.
  const NearTree tree(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}});
  double d2 = std::numeric_limits<double>::infinity();
  std::uint32_t best = NearTree::kNoTie;
  tree.search_up({std::nan(""), 0, 0}, d2, best);
  CHECK(best == NearTree::kNoTie);
  CHECK(std::isinf(d2));
}

TEST_CASE("knn: NearTree built on threads is the same tree (its visits in the same order) for every count") {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  // Enough points for subtrees below the top levels to be built on their own, some repeated.
  std::vector<Vec3> pts(30011);
  for (Vec3& p : pts) p = {u(rng), u(rng), 0.2 * u(rng)};
  for (std::size_t i = 0; i < 500; ++i) pts[20000 + i] = pts[i];
  const NearTree one(pts, 1);
  for (const int threads : {2, 3, 8}) {
    const NearTree many(pts, threads);
    for (int n = 0; n < 200; ++n) {
      const Vec3 q{u(rng), u(rng), 0.2 * u(rng)};
      std::vector<std::pair<std::uint32_t, double>> seen_one, seen_many;
      one.visit(q, 0.01, [&](std::uint32_t i, double d2) { seen_one.emplace_back(i, d2); return 0.01; });
      many.visit(q, 0.01, [&](std::uint32_t i, double d2) { seen_many.emplace_back(i, d2); return 0.01; });
      CHECK(seen_many == seen_one);
      double d_one = std::numeric_limits<double>::infinity(), d_many = d_one;
      std::uint32_t i_one = NearTree::kNoTie, i_many = NearTree::kNoTie;
      one.search_up(q, d_one, i_one);
      many.search_up(q, d_many, i_many);
      CHECK(d_many == d_one);
      CHECK(i_many == i_one);
    }
  }
}

// Points in metres on the Earth's sphere, in clusters down to a centimetre wide (many
// splits a hair apart, where a tree that bounds its gaps loosely, e.g. with floats not
// rounded outward, would lose points): both searches and the seeded batches give brute
// force's answer, ties (repeated points, lattice points at the same distance) included,
// from a cap, a candidate, or nothing.
TEST_CASE("knn: NearTree on clustered points finer than a float's step equals brute force, ties included") {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(0, 3), lattice(0, 7);
  constexpr double kR = 6.371e6;
  for (const double spread : {0.01, 3.0, 2000.0}) {
    std::vector<Vec3> pts;
    for (int cluster = 0; cluster < 40; ++cluster) {
      Vec3 c{u(rng), u(rng), u(rng)};
      c = c * (kR / std::sqrt(norm2(c)));
      for (int n = 0; n < 120; ++n) {
        // Half of them on a lattice (ties of distance and repeats), half spread.
        const Vec3 d = n % 2 ? Vec3{u(rng), u(rng), u(rng)}
                             : Vec3{double(lattice(rng)) / 7 - 0.5, double(lattice(rng)) / 7 - 0.5, 0.0};
        pts.push_back(c + d * spread);
      }
    }
    for (std::size_t i = 0; i < 200; ++i) pts.push_back(pts[i * 7]);  // repeats, larger index
    const NearTree tree(pts);
    std::vector<Vec3> queries;
    for (int n = 0; n < 3000; ++n) {
      const Vec3& p = pts[rng() % pts.size()];
      Vec3 q = n % 3 == 0 ? p : p + Vec3{u(rng), u(rng), u(rng)} * (spread * (n % 3 == 1 ? 0.5 : 20.0));
      if (n % 101 == 0) q = q * 1.5;  // far from every point
      queries.push_back(q);
    }
    std::vector<double> want_d(queries.size());
    std::vector<std::uint32_t> want_i(queries.size());
    for (std::size_t n = 0; n < queries.size(); ++n) {
      const Vec3& q = queries[n];
      double want2 = std::numeric_limits<double>::infinity();
      std::uint32_t want = 0;
      for (std::uint32_t j = 0; j < pts.size(); ++j) {
        const double d2 = norm2(pts[j] - q);
        if (d2 < want2) want2 = d2, want = j;
      }
      want_d[n] = want2, want_i[n] = want;
      double start2 = std::numeric_limits<double>::infinity();
      std::uint32_t start = NearTree::kNoTie;
      const int how = pick(rng);
      if (how == 1) start2 = want2 * 2 + 1;
      if (how >= 2) {
        start = static_cast<std::uint32_t>(rng() % pts.size());
        start2 = norm2(pts[start] - q);
      }
      double d_up = start2, d_down = start2;
      std::uint32_t i_up = start, i_down = start;
      tree.search_up(q, d_up, i_up);
      tree.search(q, d_down, i_down);
      CHECK(d_up == want2);
      CHECK(i_up == want);
      CHECK(d_down == want2);
      CHECK(i_down == want);
    }
    // The batches: seeded with the previous answer, in Morton order.
    const KdTree kd(pts);
    std::vector<double> dist(queries.size());
    std::vector<std::uint32_t> index(queries.size());
    kd.nearest(queries, dist, index);
    std::size_t bad = 0;
    for (std::size_t n = 0; n < queries.size(); ++n)
      bad += dist[n] != std::sqrt(want_d[n]) || index[n] != want_i[n];
    CHECK(bad == 0);
  }
}
