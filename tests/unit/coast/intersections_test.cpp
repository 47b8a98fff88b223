// Grid intersection search: hand-made cases, then agreement with an all-pairs oracle on
// random polygon soups (the oracle lives only here).
#include "coast/intersections.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "coast/place_pairs.h"
#include "exact/predicates.h"

using namespace sm;
using namespace sm::coast;

namespace {

// Whether two near-miss lists hold the same records in the same order: pair, distance
// and place.
bool same_near_misses(const std::vector<NearMiss>& a, const std::vector<NearMiss>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (place_pair_key(a[i]) != place_pair_key(b[i]) || a[i].distance != b[i].distance || !(a[i].where == b[i].where))
      return false;
  return true;
}

}  // namespace

TEST_CASE("intersections: crossing, touching, overlapping, folding back") {
  const std::vector<std::vector<Vec2>> cross{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}};
  auto h = find_intersections(cross);
  REQUIRE(h.size() == 2);
  CHECK(h[0].kind == HitKind::Cross);
  CHECK(h[0].loop_a == 0);
  CHECK(h[0].loop_b == 1);
  const std::vector<std::vector<Vec2>> touch{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 1}, {3, 0}, {3, 2}}};
  auto t = find_intersections(touch);
  REQUIRE(t.size() >= 1);
  CHECK(t[0].kind == HitKind::Touch);
  const std::vector<std::vector<Vec2>> apart{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2.5, 1}, {3, 0}, {3, 2}}};
  CHECK(find_intersections(apart).empty());
  const std::vector<std::vector<Vec2>> fold{{{0, 0}, {2, 0}, {1, 0}, {1, 1}}};   // 0->2 then back to 1
  auto f = find_intersections(fold);
  REQUIRE_FALSE(f.empty());
  CHECK(f[0].kind == HitKind::Overlap);
  const std::vector<std::vector<Vec2>> bowtie{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}};
  CHECK(find_intersections(bowtie).size() == 1);
}

TEST_CASE("intersections: the grid finds exactly what all pairs find") {
  std::mt19937 rng(20081234);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::vector<Vec2>> loops;
    const int nl = 3 + trial % 5;
    for (int l = 0; l < nl; ++l) {
      // Star-shaped loops of varied size so segment lengths vary a lot.
      const Vec2 c{u(rng), u(rng)};
      const double r = 0.01 + 0.2 * u(rng);
      const int n = 5 + static_cast<int>(u(rng) * 60);
      std::vector<Vec2> p;
      for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / n;
        const double rr = r * (0.5 + u(rng));
        p.push_back({c.x + rr * std::cos(a), c.y + rr * std::sin(a)});
      }
      if (trial % 4 == 0) p[2] = p[0] + 0.5 * (p[1] - p[0]) + Vec2{0, 0};   // collinear junk
      loops.push_back(p);
    }
    IntersectionStats st;
    const auto got = find_intersections(loops, &st);
    std::set<std::tuple<unsigned, unsigned, unsigned, unsigned>> want, have;
    for (const auto& h : got) have.insert({h.loop_a, h.seg_a, h.loop_b, h.seg_b});
    CHECK(have.size() == got.size());   // each pair reported once
    for (unsigned a = 0; a < loops.size(); ++a)
      for (unsigned i = 0; i < loops[a].size(); ++i)
        for (unsigned b = a; b < loops.size(); ++b)
          for (unsigned j = (a == b ? i + 1 : 0); j < loops[b].size(); ++j) {
            const unsigned na = static_cast<unsigned>(loops[a].size());
            const Vec2 p = loops[a][i], q = loops[a][(i + 1) % na];
            const Vec2 r = loops[b][j], s = loops[b][(j + 1) % loops[b].size()];
            const bool adj = a == b && ((i + 1) % na == j || (j + 1) % na == i);
            if (adj) continue;
            const Sign o1 = orient2d(p, q, r), o2 = orient2d(p, q, s), o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
            bool hit = false;
            if (o1 == Sign::Zero && o2 == Sign::Zero) {
              auto within = [](Vec2 x, Vec2 y, Vec2 z) {
                return std::min(x.x, y.x) <= z.x && z.x <= std::max(x.x, y.x) && std::min(x.y, y.y) <= z.y &&
                       z.y <= std::max(x.y, y.y);
              };
              hit = within(p, q, r) || within(p, q, s) || within(r, s, p) || within(r, s, q);
            } else {
              hit = !(o1 != Sign::Zero && o1 == o2) && !(o3 != Sign::Zero && o3 == o4);
            }
            if (hit) want.insert({a, i, b, j});
          }
    std::set<std::tuple<unsigned, unsigned, unsigned, unsigned>> have_nonadj;
    for (const auto& h : got) {
      const unsigned na = static_cast<unsigned>(loops[h.loop_a].size());
      const bool adj = h.loop_a == h.loop_b && ((h.seg_a + 1) % na == h.seg_b || (h.seg_b + 1) % na == h.seg_a);
      if (!adj) have_nonadj.insert({h.loop_a, h.seg_a, h.loop_b, h.seg_b});
    }
    CHECK(have_nonadj == want);
    CHECK(st.candidate_pairs < st.segments * st.segments / 4);   // not all pairs
  }
}

TEST_CASE("intersections: near misses measure straits") {
  const std::vector<std::vector<Vec2>> two{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1.05, 0}, {2, 0}, {2, 1}, {1.05, 1}}};
  const std::vector<std::vector<double>> w{{0.1, 0.1, 0.1, 0.1}, {0.1, 0.1, 0.1, 0.1}};
  auto m = find_near_misses(two, w);
  REQUIRE_FALSE(m.empty());
  CHECK(m[0].distance == doctest::Approx(0.05));
  const std::vector<std::vector<double>> narrow{{0.01, 0.01, 0.01, 0.01}, {0.01, 0.01, 0.01, 0.01}};
  CHECK(find_near_misses(two, narrow).empty());
}

TEST_CASE("intersections: an active mask reports exactly the hits of the active loops") {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Vec2>> loops;
  for (int l = 0; l < 12; ++l) {
    const Vec2 c{u(rng), u(rng)};
    std::vector<Vec2> p;
    for (int i = 0; i < 20; ++i) {
      const double a = 6.283185307179586 * i / 20;
      p.push_back({c.x + 0.15 * (0.5 + u(rng)) * std::cos(a), c.y + 0.15 * (0.5 + u(rng)) * std::sin(a)});
    }
    loops.push_back(p);
  }
  const auto all = find_intersections(loops);
  REQUIRE_FALSE(all.empty());
  std::vector<char> active(loops.size(), 0);
  active[3] = active[7] = 1;
  std::vector<std::vector<char>> segments_active;   // every segment of an active loop
  for (std::size_t l = 0; l < loops.size(); ++l) segments_active.emplace_back(loops[l].size(), active[l]);
  const auto some = find_intersections_at(loops, segments_active);
  std::size_t want = 0;
  for (const auto& h : all) want += active[h.loop_a] || active[h.loop_b];
  CHECK(some.size() == want);
  for (const auto& h : some) CHECK((active[h.loop_a] || active[h.loop_b]));
}

TEST_CASE("intersections: hits of the active segments are the full search's with one segment active") {
  // Random star loops crossing each other, some with collinear junk (overlaps, touches):
  // for random segment masks, find_intersections_at gives the records of the full search
  // of which one segment is marked, record for record (kind and place too: the place is
  // measured on the pair's first segment).
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Vec2>> loops;
  for (int l = 0; l < 14; ++l) {
    const Vec2 c{u(rng), u(rng)};
    const int n = 8 + 3 * l;
    std::vector<Vec2> p;
    for (int i = 0; i < n; ++i) {
      const double a = 6.283185307179586 * i / n;
      const double r = 0.15 * (0.5 + u(rng));
      p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    if (l % 3 == 0) p[2] = p[0] + 0.5 * (p[1] - p[0]);   // folds back onto its first segment
    loops.push_back(p);
  }
  loops[5][4] = loops[6][3];   // a shared vertex: a touch
  const std::vector<SegmentHit> all = find_intersections(loops);
  REQUIRE(all.size() > 40);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::vector<char>> active;
    const double frac = trial == 0 ? 0.0 : 0.05 * trial;
    for (const auto& p : loops) {
      std::vector<char> a(p.size());
      for (char& x : a) x = u(rng) < frac;
      active.push_back(a);
    }
    if (trial == 0) active[5][4] = 1;
    const std::vector<SegmentHit> some = find_intersections_at(loops, active);
    std::vector<SegmentHit> want;
    for (const SegmentHit& h : all)
      if (active[h.loop_a][h.seg_a] || active[h.loop_b][h.seg_b]) want.push_back(h);
    REQUIRE(some.size() == want.size());
    for (std::size_t i = 0; i < some.size(); ++i) {
      CHECK(place_pair_key(some[i]) == place_pair_key(want[i]));
      CHECK(some[i].kind == want[i].kind);
      CHECK(some[i].where == want[i].where);
    }
  }
}

TEST_CASE("intersections: hits of the active segments are the same on 1, 2 and 3 threads, over many chunks") {
  // Enough segments for several chunks of each kind (active entries and the segments
  // scanned, intersections.cpp): 3,500 wobbly rings over the unit square crossing their
  // neighbours, folds and a shared vertex among them. The oracle: the full search
  // restricted to the pairs with a marked segment, record for record at every count.
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Vec2>> loops;
  for (int l = 0; l < 3500; ++l) {
    const Vec2 c{u(rng), u(rng)};
    const int n = 12 + l % 40;
    std::vector<Vec2> p;
    for (int i = 0; i < n; ++i) {
      const double a = 6.283185307179586 * i / n;
      const double r = 0.012 * (0.5 + u(rng));
      p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    if (l % 7 == 0) p[2] = p[0] + 0.5 * (p[1] - p[0]);   // folds back onto its first segment
    loops.push_back(p);
  }
  loops[5][4] = loops[6][3];   // a shared vertex: a touch
  std::size_t n_segs = 0;
  for (const auto& p : loops) n_segs += p.size();
  REQUIRE(n_segs > 3 * 32768);
  const std::vector<SegmentHit> all = find_intersections(loops);
  REQUIRE(all.size() > 1000);
  for (const double frac : {0.002, 0.05, 0.4, 1.0}) {
    std::vector<std::vector<char>> active;
    for (const auto& p : loops) {
      std::vector<char> a(p.size());
      for (char& x : a) x = u(rng) < frac;
      active.push_back(a);
    }
    std::vector<SegmentHit> want;
    for (const SegmentHit& h : all)
      if (active[h.loop_a][h.seg_a] || active[h.loop_b][h.seg_b]) want.push_back(h);
    if (frac > 0.01) REQUIRE(want.size() > 100);
    for (const int threads : {1, 2, 3}) {
      CAPTURE(frac);
      CAPTURE(threads);
      const std::vector<SegmentHit> some = find_intersections_at(loops, active, threads);
      REQUIRE(some.size() == want.size());
      for (std::size_t i = 0; i < some.size(); ++i) {
        CHECK(place_pair_key(some[i]) == place_pair_key(want[i]));
        CHECK(some[i].kind == want[i].kind);
        CHECK(some[i].where == want[i].where);
      }
    }
  }
}

TEST_CASE("intersections: near pairs of the active segments are those of all pairs with one active") {
  // Wavy rings close together (many near pairs, some within one ring), segment widths
  // varying; the oracle: the full search (every segment active), which with the one-loop
  // filter is find_near_misses.
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Vec2>> loops;
  std::vector<std::vector<double>> width;
  for (int l = 0; l < 10; ++l) {
    const Vec2 c{u(rng), u(rng)};
    std::vector<Vec2> p;
    std::vector<double> w;
    for (int i = 0; i < 40; ++i) {
      const double a = 6.283185307179586 * i / 40;
      const double r = 0.12 * (1 + 0.3 * std::sin(7 * a) + 0.2 * u(rng));
      p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
      w.push_back(0.01 + 0.05 * u(rng));
    }
    loops.push_back(p);
    width.push_back(w);
  }
  using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;
  auto keys = [](const std::vector<NearMiss>& v) {
    std::vector<Key> k;
    for (const NearMiss& m : v) k.emplace_back(m.loop_a, m.seg_a, m.loop_b, m.seg_b);
    return k;
  };
  std::vector<std::vector<char>> every;
  for (const auto& p : loops) every.emplace_back(p.size(), 1);
  std::size_t searched = 0;
  const auto all = find_near_pairs(loops, width, every, &searched);
  CHECK(searched == 400);
  // With the one-loop filter: find_near_misses, in the same order.
  std::vector<Key> filtered;
  for (const NearMiss& m : all) {
    const std::uint32_t d = m.seg_a > m.seg_b ? m.seg_a - m.seg_b : m.seg_b - m.seg_a;
    if (m.loop_a != m.loop_b || std::min(d, 40 - d) >= 3) filtered.emplace_back(m.loop_a, m.seg_a, m.loop_b, m.seg_b);
  }
  CHECK(filtered == keys(find_near_misses(loops, width)));
  REQUIRE(all.size() > 50);
  // Random active sets, from one segment to half of them: exactly the pairs with one active.
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::vector<char>> active;
    const double frac = trial == 0 ? 0.0 : 0.5 * trial / 20;
    for (const auto& p : loops) {
      std::vector<char> a(p.size());
      for (char& x : a) x = u(rng) < frac;
      active.push_back(a);
    }
    if (trial == 0) active[4][17] = 1;
    const auto some = find_near_pairs(loops, width, active, &searched);
    std::vector<Key> want;
    for (const NearMiss& m : all)
      if (active[m.loop_a][m.seg_a] || active[m.loop_b][m.seg_b])
        want.emplace_back(m.loop_a, m.seg_a, m.loop_b, m.seg_b);
    CHECK(keys(some) == want);
    std::size_t on = 0;
    for (const auto& a : active) on += static_cast<std::size_t>(std::count(a.begin(), a.end(), 1));
    CHECK(searched == on);
    for (std::size_t i = 0; i < some.size(); ++i) {
      const auto it =
          std::find_if(all.begin(), all.end(), [&](const NearMiss& m) { return keys({m}) == keys({some[i]}); });
      REQUIRE(it != all.end());
      CHECK(it->distance == some[i].distance);
    }
  }
}

TEST_CASE("intersections: near misses searched again for the changed loops are the full search's") {
  // Wavy rings; between two searches some rings move, one is emptied (a loop merged away)
  // and one gets new widths: the pairs kept from before plus those searched for the changed
  // loops are find_near_misses of the new rings, record for record.
  std::mt19937 rng(977);
  std::uniform_real_distribution<double> u(0, 1);
  auto ring = [&](Vec2 c, int n) {
    std::vector<Vec2> p;
    for (int i = 0; i < n; ++i) {
      const double a = 6.283185307179586 * i / n;
      const double r = 0.12 * (1 + 0.3 * std::sin(5 * a) + 0.2 * u(rng));
      p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    return p;
  };
  std::vector<std::vector<Vec2>> loops;
  std::vector<std::vector<double>> width;
  for (int l = 0; l < 12; ++l) {
    loops.push_back(ring({u(rng), u(rng)}, 30 + 3 * l));
    std::vector<double> w;
    for (std::size_t i = 0; i < loops.back().size(); ++i) w.push_back(0.01 + 0.05 * u(rng));
    width.push_back(w);
  }
  std::vector<NearMiss> near = find_near_misses(loops, width);
  REQUIRE(near.size() > 50);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<char> changed(loops.size(), 0);
    const auto moved = static_cast<std::size_t>(trial % 12), emptied = static_cast<std::size_t>((trial * 5 + 3) % 12);
    loops[moved] = ring({u(rng), u(rng)}, 40);
    width[moved].assign(40, 0.03);
    changed[moved] = 1;
    if (trial % 2 == 0 && emptied != moved) {
      loops[emptied].clear();
      width[emptied].clear();
      changed[emptied] = 1;
    }
    const auto rewidthed = static_cast<std::size_t>((trial * 7 + 1) % 12);
    if (!loops[rewidthed].empty()) {
      for (double& w : width[rewidthed]) w *= 1.5;
      changed[rewidthed] = 1;
    }
    std::vector<std::vector<char>> active(loops.size()), none(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l) {
      active[l].assign(loops[l].size(), changed[l]);
      none[l].assign(loops[l].size(), 0);
    }
    const std::vector<NearMiss> full = find_near_misses(loops, width);
    const std::vector<NearMiss> again = find_near_misses_again(loops, width, active, near);
    CHECK(same_near_misses(again, full));
    // The segments left unmarked keep their old pairs: marking none misses the changes.
    if (trial == 0) CHECK(!same_near_misses(find_near_misses_again(loops, width, none, near), full));
    near = again;
  }
}

TEST_CASE("intersections: near misses after loops are joined are the full search's, renumbered") {
  // Rings close together; pairs of them joined as a strait merge joins two islands (one
  // polygon from each's segment k + 1 round, the other emptied): the pass before's records
  // renumbered, with the segments at the bridges searched again, are find_near_misses of
  // the joined polygons, record for record.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Vec2>> loops;
  std::vector<std::vector<double>> width;
  for (int l = 0; l < 10; ++l) {
    const Vec2 c{0.6 * u(rng), 0.6 * u(rng)};
    const int n = 8 + 4 * l;
    std::vector<Vec2> p;
    for (int i = 0; i < n; ++i) {
      const double a = 6.283185307179586 * i / n;
      const double r = 0.1 * (1 + 0.3 * std::sin(4 * a) + 0.2 * u(rng));
      p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    loops.push_back(p);
    std::vector<double> w;
    for (int i = 0; i < n; ++i) w.push_back(0.02 + 0.04 * u(rng));
    width.push_back(w);
  }
  std::vector<NearMiss> near = find_near_misses(loops, width);
  REQUIRE(near.size() > 30);
  const std::pair<std::uint32_t, std::uint32_t> rounds[3][2] = {{{0, 1}, {2, 3}}, {{4, 0}, {5, 6}}, {{2, 7}, {8, 9}}};
  for (const auto& round : rounds) {
    std::vector<LoopJoin> joins;
    for (const auto& [into, from] : round) {
      const auto na = static_cast<std::uint32_t>(loops[into].size()),
                 nb = static_cast<std::uint32_t>(loops[from].size());
      const std::uint32_t ka = static_cast<std::uint32_t>(rng() % na), kb = static_cast<std::uint32_t>(rng() % nb);
      std::vector<Vec2> p;
      std::vector<double> w;
      for (std::uint32_t i = 1; i <= na; ++i)
        p.push_back(loops[into][(ka + i) % na]), w.push_back(width[into][(ka + i) % na]);
      for (std::uint32_t i = 1; i <= nb; ++i)
        p.push_back(loops[from][(kb + i) % nb]), w.push_back(width[from][(kb + i) % nb]);
      loops[into] = p;
      width[into] = w;
      loops[from].clear();
      width[from].clear();
      joins.push_back({into, from, ka, kb, na, nb});
    }
    std::vector<std::vector<char>> active(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l) active[l].assign(loops[l].size(), 0);
    std::vector<std::vector<char>> active_shuffled = active;
    std::vector<NearMiss> renumbered = near;
    renumber_for_joins(joins, renumbered, active);
    // The records sorted before stay sorted (find_near_misses_again takes them as they are).
    CHECK(std::is_sorted(renumbered.begin(), renumbered.end(), [](const NearMiss& a, const NearMiss& b) {
      return place_pair_key(a) < place_pair_key(b);
    }));
    const std::vector<NearMiss> full = find_near_misses(loops, width);
    const std::vector<NearMiss> again = find_near_misses_again(loops, width, active, renumbered);
    CHECK(same_near_misses(again, full));
    // The same from the records in any order, searched on two threads.
    std::vector<NearMiss> shuffled = near;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    renumber_for_joins(joins, shuffled, active_shuffled);
    CHECK(same_near_misses(find_near_misses_again(loops, width, active_shuffled, shuffled, 2), full));
    near = again;
  }
}

TEST_CASE("intersections: near pairs are the same records on any thread count, past one chunk") {
  // 600 wavy rings (24,000 segments, so the search's cells and segments each come in
  // several fixed chunks): the full search is find_near_misses record for record, and
  // every thread count gives the same list, the active segments a third of them or all.
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Vec2>> loops;
  std::vector<std::vector<double>> width;
  for (int l = 0; l < 600; ++l) {
    const Vec2 c{20 * u(rng), 20 * u(rng)};
    std::vector<Vec2> p;
    std::vector<double> w;
    for (int i = 0; i < 40; ++i) {
      const double a = 6.283185307179586 * i / 40;
      const double r = 0.5 * (1 + 0.3 * std::sin(7 * a) + 0.2 * u(rng));
      p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
      w.push_back(0.05 + 0.2 * u(rng));
    }
    loops.push_back(p);
    width.push_back(w);
  }
  std::vector<std::vector<char>> every, third;
  for (const auto& p : loops) {
    every.emplace_back(p.size(), 1);
    std::vector<char> a(p.size());
    for (char& x : a) x = u(rng) < 0.33;
    third.push_back(a);
  }
  const auto all = find_near_pairs(loops, width, every, nullptr, 1);
  std::vector<NearMiss> filtered;
  for (const NearMiss& m : all) {
    const std::uint32_t d = m.seg_a > m.seg_b ? m.seg_a - m.seg_b : m.seg_b - m.seg_a;
    if (m.loop_a != m.loop_b || std::min(d, 40 - d) >= 3) filtered.push_back(m);
  }
  REQUIRE(filtered.size() > 1000);
  CHECK(same_near_misses(filtered, find_near_misses(loops, width)));
  const auto some = find_near_pairs(loops, width, third, nullptr, 1);
  REQUIRE(some.size() > 500);
  for (int threads : {2, 3, 8}) {
    CHECK(same_near_misses(find_near_pairs(loops, width, every, nullptr, threads), all));
    CHECK(same_near_misses(find_near_pairs(loops, width, third, nullptr, threads), some));
  }
}
