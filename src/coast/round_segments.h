// The segments of passage closing's rounds (passages.cpp, round_near_misses): each live
// loop's kept segments numbered loop after loop, and which of them are the same as in the
// last round (the same start node and the same end node: a node's point never moves, and a
// node that left the live loops never comes back), so that only the new ones are searched.
//
// Once every live loop's ring was walked and all the round's segments sorted by start node
// each round, to be matched with the last round's: at 3 km on the full GSHHG a third of a
// round's candidate search, for the few loops a round changes. A loop the last round did
// not change has the same segments in the same order, so its match is known without a
// look; only the changed loops' segments (theirs now and those of the loops changed or
// gone since) are sorted and matched. A node is on one ring: a changed loop's node was on
// no unchanged loop last round, so that match is the full one's (round_segments_test.cpp
// holds it to the full walk and sort after random cuts and joins).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sm::coast {

class RoundSegments {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  /// One round's segments and their match with the last round's.
  struct Round {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> at;   // per segment: its loop and position
    std::vector<std::vector<char>> active;   // per loop, per segment: 1 when new since the last round
    std::vector<std::uint32_t> renumber;     // per last-round segment: its number now, or kNone
  };
  /// The next round, loops 0 .. n_loops - 1 (a loop's number never changes; loops are only
  /// added). `live(l)`: whether loop l is live; `changed(l)`: whether its ring may differ
  /// from the last round's (true for a loop made since; never false for one that differs);
  /// `ids_of(l, ids, keys)`: fills `ids` with a live loop's kept node ids in ring order and
  /// `keys` with a number for each (below n_keys) that most points keep between rounds
  /// (passages.cpp: its rope point). A key is only a hint: where it names no segment of the
  /// last round with the same ends, the segment is matched by its start node.
  template <class Live, class Changed, class IdsOf>
  Round next(std::size_t n_loops, std::size_t n_keys, Live&& live, Changed&& changed, IdsOf&& ids_of) {
    // Sized once a round to the keys' bound, with an eighth to spare: grown key by key it
    // doubled (8 bytes a rope point, the first round at the import's peak).
    if (n_keys > place_.capacity()) place_.reserve(n_keys + n_keys / 8);
    if (n_keys > place_.size()) place_.resize(n_keys, kNoPlace);
    Round r;
    r.active.resize(n_loops);
    r.renumber.assign(n_segments_, kNone);
    ids_.resize(n_loops);
    std::vector<std::size_t> first(n_loops, 0);
    // The changed loops' rings now, set in place once all are matched (a key may name a
    // segment of a loop later in the order).
    std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> remade;
    std::vector<std::uint32_t> keys;
    for (std::uint32_t l = 0; l < n_loops; ++l) {
      if (!live(l)) continue;
      first[l] = r.at.size();
      std::size_t k = ids_[l].size();
      if (changed(l)) {
        remade.emplace_back(l, std::vector<std::uint32_t>());
        keys.clear();
        ids_of(l, remade.back().second, keys);
        k = remade.back().second.size();
        r.active[l].assign(k, 1);
        match_by_keys(l, remade.back().second, keys, first[l], r);
      } else {
        for (std::size_t j = 0; j < k; ++j) r.renumber[first_[l] + j] = static_cast<std::uint32_t>(first[l] + j);
        r.active[l].assign(k, 0);
      }
      for (std::size_t j = 0; j < k; ++j) r.at.push_back({l, static_cast<std::uint32_t>(j)});
    }
    match_the_rest(n_loops, live, changed, remade, first, r);
    for (std::uint32_t l = 0; l < n_loops; ++l)
      if (!live(l)) std::vector<std::uint32_t>().swap(ids_[l]);
    for (auto& [l, ids] : remade) ids_[l] = std::move(ids);
    first_ = std::move(first);
    n_segments_ = r.at.size();
    return r;
  }
  /// The number of loop l's first segment in the last round made.
  std::size_t first(std::uint32_t l) const { return first_[l]; }
  /// Frees everything (the rounds are over).
  void clear() { *this = RoundSegments(); }

 private:
  struct Segment {
    std::uint32_t start, end, number;
  };
  // A segment's place: its loop and position.
  struct Place {
    std::uint32_t loop, pos;
  };
  static constexpr Place kNoPlace{0xFFFFFFFFu, 0};
  // Matches changed loop l's segments (its ring `ids` now, numbered from `first`) through
  // their start points' keys, and records their places there for the next round.
  void match_by_keys(std::uint32_t l, const std::vector<std::uint32_t>& ids, const std::vector<std::uint32_t>& keys,
                     std::size_t first, Round& r);
  // The changed loops' segments left unmatched, and the last round's segments of loops
  // changed or gone since left unmatched, matched by start node (sorted).
  template <class Live, class Changed>
  void match_the_rest(std::size_t n_loops, Live&& live, Changed&& changed,
                      const std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>>& remade,
                      const std::vector<std::size_t>& first, Round& r) const {
    std::vector<Segment> before, now;
    for (std::uint32_t l = 0; l < n_loops && l < first_.size(); ++l)
      if (!live(l) || changed(l)) {
        const std::size_t from = first_[l];
        add_segments(ids_[l], from, [&](std::size_t j) { return r.renumber[from + j] == kNone; }, before);
      }
    if (before.empty()) return;   // nothing to match (the first round: every segment is new)
    for (const auto& loop : remade) {
      const std::vector<char>& active = r.active[loop.first];
      add_segments(loop.second, first[loop.first], [&](std::size_t j) { return active[j] != 0; }, now);
    }
    match(before, now, r);
  }
  // ids' segments (ring order, the last one closing the ring) numbered from `first`, those
  // at the positions j where keep(j).
  template <class Keep>
  static void add_segments(const std::vector<std::uint32_t>& ids, std::size_t first, Keep&& keep,
                           std::vector<Segment>& out) {
    const std::size_t k = ids.size();
    for (std::size_t j = 0; j < k; ++j)
      if (keep(j)) out.push_back({ids[j], ids[j + 1 < k ? j + 1 : 0], static_cast<std::uint32_t>(first + j)});
  }
  static void match(std::vector<Segment>& before, std::vector<Segment>& now, Round& r);
  std::vector<std::vector<std::uint32_t>> ids_;   // per loop live in the last round: its kept node ids then
  std::vector<std::size_t> first_;                 // per loop: its first segment's number in the last round
  std::vector<Place> place_;                       // per key: the place of the segment its point started
  std::size_t n_segments_ = 0;                     // the last round's segments
};

}  // namespace sm::coast
