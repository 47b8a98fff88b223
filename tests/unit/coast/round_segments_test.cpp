// RoundSegments (coast/round_segments.h) against the full walk it replaced in passage
// closing's rounds (passages.cpp, round_near_misses): every live loop's segments listed,
// sorted by start node and matched with the last round's list. Rounds of random cuts
// (one ring into two), joins (two into one), points put back or taken out, loops dropped
// and loops marked changed that did not change, on rings of node ids as the pool's.
#include "coast/round_segments.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

using namespace sm::coast;

namespace {

struct Loop {
  std::vector<std::uint32_t> ids;
  bool live = true;
  bool changed = true;
};

// The full walk: every live loop's segments numbered loop after loop, sorted by start node
// and matched with the last round's sorted list.
struct FullWalk {
  struct Segment {
    std::uint32_t start, end, number;
  };
  std::vector<Segment> last;
  RoundSegments::Round next(const std::vector<Loop>& loops, std::vector<std::size_t>& first) {
    RoundSegments::Round r;
    r.active.resize(loops.size());
    first.assign(loops.size(), 0);
    std::vector<Segment> segs;
    for (std::uint32_t l = 0; l < loops.size(); ++l) {
      if (!loops[l].live) continue;
      const auto& ids = loops[l].ids;
      const std::size_t k = ids.size();
      first[l] = r.at.size();
      r.active[l].assign(k, 1);
      for (std::size_t j = 0; j < k; ++j) {
        segs.push_back({ids[j], ids[(j + 1) % k], static_cast<std::uint32_t>(r.at.size())});
        r.at.push_back({l, static_cast<std::uint32_t>(j)});
      }
    }
    auto by_start = [](const Segment& x, const Segment& y) { return x.start < y.start; };
    std::sort(segs.begin(), segs.end(), by_start);
    r.renumber.assign(last.size(), RoundSegments::kNone);
    for (const Segment& s : segs) {
      const auto it = std::lower_bound(last.begin(), last.end(), s, by_start);
      if (it == last.end() || it->start != s.start || it->end != s.end) continue;
      r.renumber[it->number] = s.number;
      r.active[r.at[s.number].first][r.at[s.number].second] = 0;
    }
    last = std::move(segs);
    return r;
  }
};

std::vector<std::uint32_t> rotated(const std::vector<std::uint32_t>& ids, std::size_t from) {
  std::vector<std::uint32_t> out(ids.begin() + static_cast<std::ptrdiff_t>(from), ids.end());
  out.insert(out.end(), ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(from));
  return out;
}

// One random change of the loops (bounded: one step of at most the loops' points).
void change(std::vector<Loop>& loops, std::uint32_t& next_id, std::mt19937& rng) {
  std::vector<std::uint32_t> live;
  for (std::uint32_t l = 0; l < loops.size(); ++l)
    if (loops[l].live) live.push_back(l);
  if (live.empty()) return;
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  const std::uint32_t a = live[pick(live.size())];
  const std::size_t k = loops[a].ids.size();
  switch (rng() % 6) {
    case 0: {   // a cut of one ring into two: a1 ... b0 and b1 ... a0
      if (k < 6) return;
      const std::size_t i = pick(k), d = 2 + pick(k - 3);
      const std::vector<std::uint32_t> r = rotated(loops[a].ids, (i + 1) % k);
      loops[a].live = false;
      loops.push_back({std::vector<std::uint32_t>(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(d)), true, true});
      loops.push_back({std::vector<std::uint32_t>(r.begin() + static_cast<std::ptrdiff_t>(d), r.end()), true, true});
      return;
    }
    case 1: {   // a cut joining two rings
      const std::uint32_t b = live[pick(live.size())];
      if (b == a) return;
      std::vector<std::uint32_t> r = rotated(loops[a].ids, pick(k));
      const std::vector<std::uint32_t> s = rotated(loops[b].ids, pick(loops[b].ids.size()));
      r.insert(r.end(), s.begin(), s.end());
      loops[a].live = loops[b].live = false;
      loops.push_back({r, true, true});
      return;
    }
    case 2: {   // points put back on a segment (a refused cut's)
      const std::size_t j = pick(k), n = 1 + pick(3);
      for (std::size_t t = 0; t < n; ++t)
        loops[a].ids.insert(loops[a].ids.begin() + static_cast<std::ptrdiff_t>(j + 1), next_id++);
      loops[a].changed = true;
      return;
    }
    case 3:   // a point taken out (a dam's wedge cut off), the ring maybe made again from elsewhere
      if (k < 5) return;
      loops[a].ids.erase(loops[a].ids.begin() + static_cast<std::ptrdiff_t>(pick(k)));
      if (rng() % 2) loops[a].ids = rotated(loops[a].ids, pick(k - 1));
      loops[a].changed = true;
      return;
    case 4:   // dropped as narrow water
      loops[a].live = false;
      return;
    default:   // marked changed, left as it was
      loops[a].changed = true;
      return;
  }
}

}  // namespace

TEST_CASE("RoundSegments matches the full walk and sort after random cuts and joins, whatever the keys") {
  std::size_t kept = 0;   // segments that outlived a round, over every seed
  for (std::uint32_t seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::vector<Loop> loops;
    std::uint32_t next_id = 0;
    const std::size_t n_loops = 1 + rng() % 8;
    for (std::size_t l = 0; l < n_loops; ++l) {
      Loop f;
      const std::size_t k = 3 + rng() % 40;
      for (std::size_t j = 0; j < k; ++j) f.ids.push_back(next_id++);
      loops.push_back(f);
    }
    RoundSegments incremental;
    FullWalk full;
    // Each point's key: mostly kept between rounds (as a rope point), sometimes a new one or
    // one another point had (a rope made again, its points reused), from a small range.
    std::vector<std::uint32_t> keys;
    auto key_of = [&](std::uint32_t id) {
      while (keys.size() <= id) keys.push_back(static_cast<std::uint32_t>(keys.size()));
      return keys[id];
    };
    for (int round = 0; round < 30; ++round) {
      std::vector<std::size_t> first;
      const RoundSegments::Round want = full.next(loops, first);
      const RoundSegments::Round got = incremental.next(
          loops.size(), keys.size() + 8 + next_id, [&](std::uint32_t l) { return loops[l].live; },
          [&](std::uint32_t l) { return loops[l].changed; },
          [&](std::uint32_t l, std::vector<std::uint32_t>& ids, std::vector<std::uint32_t>& point_keys) {
            ids = loops[l].ids;
            for (std::uint32_t id : ids) point_keys.push_back(key_of(id));
          });
      CHECK(got.at == want.at);
      CHECK(got.active == want.active);
      CHECK(got.renumber == want.renumber);
      for (std::uint32_t l = 0; l < loops.size(); ++l)
        if (loops[l].live) CHECK(incremental.first(l) == first[l]);
      for (std::uint32_t r : got.renumber) kept += r != RoundSegments::kNone;
      for (Loop& f : loops) f.changed = false;
      for (std::uint32_t& k : keys)
        if (rng() % 10 == 0) k = static_cast<std::uint32_t>(rng() % (keys.size() + 8));
      const int changes = 1 + static_cast<int>(rng() % 3);
      for (int c = 0; c < changes; ++c) change(loops, next_id, rng);
    }
  }
  CHECK(kept > 1000);
}
