// sort_place_pairs_on and sort_place_pairs_by_keys (coast/place_pairs.h): the key sorts of pair
// records give sort_place_pairs' order, record for record, for loops of every size (empty ones too).
#include "coast/place_pairs.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <set>
#include <tuple>
#include <vector>

using namespace sm::coast;

namespace {
struct Rec {
  std::uint32_t loop_a, seg_a, loop_b, seg_b;
  int tag;
};
}  // namespace

TEST_CASE("place pairs: the one-key sort on loops orders as sort_place_pairs") {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::vector<int>> loops(1 + rng() % 30);
    for (auto& l : loops) l.resize(rng() % 3 == 0 ? 0 : 1 + rng() % 200);
    std::vector<Rec> v;
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>> seen;
    for (int i = 0; i < 500; ++i) {
      const auto la = static_cast<std::uint32_t>(rng() % loops.size());
      const auto lb = static_cast<std::uint32_t>(rng() % loops.size());
      if (loops[la].empty() || loops[lb].empty()) continue;
      Rec r{la, static_cast<std::uint32_t>(rng() % loops[la].size()), lb,
            static_cast<std::uint32_t>(rng() % loops[lb].size()), i};
      order_places(r);
      if (seen.insert({r.loop_a, r.seg_a, r.loop_b, r.seg_b}).second) v.push_back(r);
    }
    std::vector<Rec> want = v, got = v, by_keys = v;
    sort_place_pairs(want);
    sort_place_pairs_on(got, loops);
    sort_place_pairs_by_keys(by_keys);
    REQUIRE(got.size() == want.size());
    REQUIRE(by_keys.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i].tag == want[i].tag);
    for (std::size_t i = 0; i < by_keys.size(); ++i) CHECK(by_keys[i].tag == want[i].tag);
  }
}

// sort_place_pairs_by_keys against the four-field comparison (std::stable_sort: ties keep
// their input order) on records with duplicates, ties in each field, and indices small enough
// for the one-key packing or large enough (near 2^32) to take the two-key sort.
TEST_CASE("place pairs: sort_place_pairs_by_keys orders as a stable sort by place_pair_key") {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 200; ++trial) {
    const int kind = trial % 4;   // 0, 1: small; 2: large segs; 3: large loops
    const std::uint32_t loop_range = kind == 3 ? 0xFFFFFFFFu : kind == 0 ? 4u : 1 + rng() % 3000;
    const std::uint32_t seg_range = kind == 2 ? 0xFFFFFFFFu : kind == 0 ? 5u : 1 + rng() % 100000;
    auto loop = [&] {
      const std::uint32_t r = static_cast<std::uint32_t>(rng());
      return rng() % 4 == 0 ? loop_range - 1 - r % 3 : r % loop_range;   // the top too
    };
    auto seg = [&] {
      const std::uint32_t r = static_cast<std::uint32_t>(rng());
      return rng() % 4 == 0 ? seg_range - 1 - r % 3 : r % seg_range;
    };
    std::vector<Rec> v;
    const int n = static_cast<int>(rng() % 400);
    for (int i = 0; i < n; ++i) {
      if (!v.empty() && rng() % 5 == 0) {   // a duplicate pair, or one sharing a place
        Rec r = v[rng() % v.size()];
        if (rng() % 2) r.seg_b = seg();
        r.tag = i;
        order_places(r);
        v.push_back(r);
        continue;
      }
      Rec r{loop(), seg(), loop(), seg(), i};
      order_places(r);
      v.push_back(r);
    }
    std::vector<Rec> want = v, got = v;
    std::stable_sort(want.begin(), want.end(),
                     [](const Rec& a, const Rec& b) { return place_pair_key(a) < place_pair_key(b); });
    sort_place_pairs_by_keys(got);
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i].tag == want[i].tag);
  }
}
