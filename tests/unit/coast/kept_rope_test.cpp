// KeptRopes (coast/kept_rope.h) against rings held as vectors and cut by copying them, as
// passage closing once did (passages.cpp): the same rings after many cuts and joins, and a
// cut's work that does not grow with the ring's size.
#include "coast/kept_rope.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace sm;
using namespace sm::coast;

namespace {

using Items = std::vector<KeptRopes::Item>;

// Positions from .. to of a ring, inclusive, cyclic: the copying version's kept_range.
Items copy_range(const Items& f, std::size_t from, std::size_t to) {
  const std::size_t k = f.size(), len = (to + k - from) % k + 1;
  Items out;
  for (std::size_t i = 0; i < len; ++i) out.push_back(f[(from + i) % k]);
  return out;
}

Items rope_items(const KeptRopes& ropes, KeptRopes::Rope r) {
  Items out;
  ropes.for_each(r, [&](KeptRopes::TreeNode t) { out.push_back({ropes.id(t), ropes.uv(t), ropes.metres(t)}); });
  return out;
}

bool same(const Items& a, const Items& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].id != b[i].id || !(a[i].uv == b[i].uv) || a[i].metres != b[i].metres) return false;
  return true;
}

// The first point of least (y, x), as ring_orientation finds it.
std::size_t first_lowest(const Items& f) {
  std::size_t lo = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (f[i].uv.y < f[lo].uv.y || (f[i].uv.y == f[lo].uv.y && f[i].uv.x < f[lo].uv.x)) lo = i;
  return lo;
}

// A ring of n points on a wobbly circle, ids from `first`, every 7th the same low point.
Items wobbly_ring(std::size_t n, std::uint32_t first, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  Items out;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
    Vec2 p{std::cos(a) + jitter(rng), std::sin(a) + jitter(rng)};
    if (i % 7 == 3) p = {0.25, -1.0};   // ties for the lowest: the first one counts
    out.push_back({first + static_cast<std::uint32_t>(i), p, 1.0 + jitter(rng)});
  }
  return out;
}

}  // namespace

TEST_CASE("kept ropes: many cuts and joins give the rings that copying gives") {
  std::mt19937 rng(20261206);
  KeptRopes ropes;
  std::vector<Items> copies;
  std::vector<KeptRopes::Rope> live;
  std::uint32_t next_id = 0;
  for (int i = 0; i < 6; ++i) {
    const Items ring = wobbly_ring(200 + 300 * static_cast<std::size_t>(i), next_id, rng);
    next_id += static_cast<std::uint32_t>(ring.size());
    copies.push_back(ring);
    live.push_back(ropes.make(ring));
  }
  std::size_t cuts = 0, joins = 0;
  for (int step = 0; step < 600; ++step) {
    std::uniform_int_distribution<std::size_t> pick(0, copies.size() - 1);
    const std::size_t a = pick(rng);
    const std::size_t ka = copies[a].size();
    if (ka < 8) continue;
    std::uniform_int_distribution<std::size_t> pos(0, ka - 1);
    const std::size_t ja = pos(rng);
    if (step % 5 == 4 && copies.size() > 1) {
      // A join of ring a at ja and ring b at jb: a1 ... a0 then b1 ... b0.
      std::size_t b = pick(rng);
      if (b == a) b = (a + 1) % copies.size();
      const std::size_t kb = copies[b].size();
      const std::size_t jb = std::uniform_int_distribution<std::size_t>(0, kb - 1)(rng);
      Items joined = copy_range(copies[a], (ja + 1) % ka, ja);
      const Items tail = copy_range(copies[b], (jb + 1) % kb, jb);
      joined.insert(joined.end(), tail.begin(), tail.end());
      joined[ka - 1].metres = 7.5;   // the dams a0 -> b1 and b0 -> a1
      joined.back().metres = 8.5;
      KeptRopes::Rope r = ropes.join(ropes.rotate(live[a], (ja + 1) % ka), ropes.rotate(live[b], (jb + 1) % kb));
      ropes.set_metres(ropes.at(r, ka - 1), 7.5);
      ropes.set_metres(ropes.at(r, ka + kb - 1), 8.5);
      const std::size_t hi = std::max(a, b), lo = std::min(a, b);
      copies.erase(copies.begin() + static_cast<std::ptrdiff_t>(hi));
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(hi));
      copies[lo] = std::move(joined);
      live[lo] = r;
      ++joins;
      continue;
    }
    // A cut of ring a at segments ja and jb: a1 ... b0 and b1 ... a0.
    std::size_t jb = pos(rng);
    if (jb == ja) continue;
    Items first = copy_range(copies[a], (ja + 1) % ka, jb), second = copy_range(copies[a], (jb + 1) % ka, ja);
    first.back().metres = 2.5;
    second.back().metres = 3.5;
    const std::size_t len1 = first.size();
    auto [r1, r2] = ropes.split(ropes.rotate(live[a], (ja + 1) % ka), len1);
    ropes.set_metres(ropes.at(r1, len1 - 1), 2.5);
    ropes.set_metres(ropes.at(r2, ropes.size(r2) - 1), 3.5);
    copies[a] = std::move(first);
    live[a] = r1;
    if (second.size() < 4) {   // a piece dropped
      ropes.release(r2);
    } else {
      copies.push_back(std::move(second));
      live.push_back(r2);
    }
    ++cuts;
  }
  CHECK(cuts > 200);
  CHECK(joins > 50);
  REQUIRE(copies.size() == live.size());
  for (std::size_t l = 0; l < copies.size(); ++l) {
    const Items& f = copies[l];
    const KeptRopes::Rope r = live[l];
    REQUIRE(ropes.size(r) == f.size());
    CHECK(same(rope_items(ropes, r), f));
    CHECK(ropes.rank(ropes.lowest(r)) == first_lowest(f));
    double run = 0;
    for (std::size_t j = 0; j < f.size(); ++j) {
      const KeptRopes::TreeNode t = ropes.at(r, j);
      CHECK(ropes.id(t) == f[j].id);
      CHECK(ropes.rank(t) == j);
      CHECK(ropes.root_of(t) == r);
      // The next position by one step from t (follow_find in passages.cpp), none after the last.
      CHECK(ropes.next(t) == (j + 1 < f.size() ? ropes.at(r, j + 1) : KeptRopes::kNone));
      // Summed in another order: within the rounding of a sum of f.size() terms.
      CHECK(std::abs(ropes.prefix_metres(r, j) - run) <= 4e-16 * static_cast<double>(f.size()) * (run + 1));
      run += f[j].metres;
    }
    CHECK(std::abs(ropes.total_metres(r) - run) <= 4e-16 * static_cast<double>(f.size()) * run);
  }
}

TEST_CASE("kept ropes: a cut's work does not grow with the ring's size") {
  // A copy per cut reads the ring: 100 times more work on a ring 100 times larger. A rope
  // cut goes down a few paths of the tree: a few times (log n)^2 with the spines below.
  auto work_per_cut = [](std::size_t n) {
    std::mt19937 rng(7);
    KeptRopes ropes;
    KeptRopes::Rope r = ropes.make(wobbly_ring(n, 0, rng));
    const std::size_t before = ropes.work();
    constexpr int kCuts = 2000;
    for (int c = 0; c < kCuts; ++c) {
      // Cut a small inlet (three points dropped) and keep the rest, as closing an inlet of
      // a continent does; then three new points go in so that the size stays.
      const std::size_t k = ropes.size(r);
      const std::size_t ja = std::uniform_int_distribution<std::size_t>(0, k - 1)(rng);
      auto [rest, inlet] = ropes.split(ropes.rotate(r, (ja + 1) % k), k - 3);
      ropes.set_metres(ropes.at(rest, k - 4), 1.0);
      ropes.release(inlet);
      const Items fresh{{0, {0, -2}, 1}, {1, {0.5, -2}, 1}, {2, {1, -2}, 1}};
      r = ropes.join(rest, ropes.make(fresh));
    }
    return static_cast<double>(ropes.work() - before) / kCuts;
  };
  const double small = work_per_cut(1000), large = work_per_cut(100000);
  MESSAGE("rope work per cut: ", small, " at 1,000 points, ", large, " at 100,000");
  // Each tree node pulled on a path also walks the spine of a child subtree to the point
  // next to it (the mean width's link segments, kept_rope.cpp): log n nodes a pull, so
  // (log n)^2 a path: 3 times more at 100 times the points (1.5 times without the spines).
  CHECK(large < 4.0 * small);
  CHECK(large < 1200);
}

TEST_CASE("kept ropes: a run of consecutive points stepped from one descent is the points descended to") {
  // Passage closing reads up to nine consecutive ring points round a cut's segments
  // (passages.cpp: sharp_dam_end, trim_dam_wedges); a run steps with next() from one
  // descent, wrapping from the last point to the first, as at() at (j + i) mod size gives.
  std::mt19937 rng(11);
  KeptRopes ropes;
  // A ring cut and joined again and again, so that its tree is not the one make() built.
  KeptRopes::Rope r = ropes.make(wobbly_ring(500, 0, rng));
  for (int c = 0; c < 200; ++c) {
    const std::size_t k = ropes.size(r);
    const std::size_t j = std::uniform_int_distribution<std::size_t>(0, k - 1)(rng);
    auto [a, b] = ropes.split(ropes.rotate(r, j), k / 3);
    r = ropes.join(b, a);
  }
  const std::size_t n = ropes.size(r);
  auto check_runs = [&](KeptRopes::Rope rope, std::size_t len) {
    const std::size_t k = ropes.size(rope);
    for (std::size_t j = 0; j < k + 3; ++j) {
      std::vector<KeptRopes::TreeNode> out(len);
      const std::size_t before = ropes.work();
      ropes.run(rope, j, out);
      const std::size_t run_work = ropes.work() - before;
      const std::size_t one_descent_before = ropes.work();
      (void)ropes.at(rope, j % k);
      CHECK(run_work == ropes.work() - one_descent_before);   // one descent, not one a point
      for (std::size_t i = 0; i < len; ++i) CHECK(out[i] == ropes.at(rope, (j + i) % k));
    }
  };
  check_runs(r, 9);   // across tree nodes and round the ends (j near 0 and near n)
  CHECK(n == 500);
  // A ring shorter than the run: it wraps more than once.
  KeptRopes::Rope small = ropes.make(wobbly_ring(3, 1000, rng));
  check_runs(small, 8);
}
