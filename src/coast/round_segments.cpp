// Matching a closing round's changed segments with the last round's (round_segments.h).
#include "coast/round_segments.h"

#include <algorithm>

#include "base/check.h"

namespace sm::coast {

void RoundSegments::match_by_keys(std::uint32_t l, const std::vector<std::uint32_t>& ids,
                                  const std::vector<std::uint32_t>& keys, std::size_t first, Round& r) {
  const std::size_t k = ids.size();
  for (std::size_t j = 0; j < k; ++j) {
    const std::uint32_t key = keys[j], start = ids[j], end = ids[j + 1 < k ? j + 1 : 0];
    SM_ASSERT(key < place_.size(), "RoundSegments: a key past the bound given (coast/round_segments.cpp)");
    const Place was = place_[key];
    place_[key] = {l, static_cast<std::uint32_t>(j)};
    // The last round's segment there, when it has the same ends: a node starts one segment
    // a round (it is on one ring), so it is the one the start node would find.
    if (was.loop >= ids_.size()) continue;
    const std::vector<std::uint32_t>& then = ids_[was.loop];
    if (was.pos >= then.size() || then[was.pos] != start) continue;
    if (then[was.pos + 1 < then.size() ? was.pos + 1 : 0] != end) continue;
    r.renumber[first_[was.loop] + was.pos] = static_cast<std::uint32_t>(first + j);
    r.active[l][j] = 0;
  }
}

void RoundSegments::match(std::vector<Segment>& before, std::vector<Segment>& now, Round& r) {
  // A node starts one segment a round (it is on one ring): the two lists sorted by start
  // node are matched in one pass.
  auto by_start = [](const Segment& x, const Segment& y) { return x.start < y.start; };
  std::sort(before.begin(), before.end(), by_start);
  std::sort(now.begin(), now.end(), by_start);
  for (std::size_t i = 0, o = 0; i < now.size(); ++i) {
    while (o < before.size() && before[o].start < now[i].start) ++o;
    if (o == before.size() || before[o].start != now[i].start || before[o].end != now[i].end) continue;
    r.renumber[before[o].number] = now[i].number;
    const auto [l, j] = r.at[now[i].number];
    r.active[l][j] = 0;
  }
}

}  // namespace sm::coast
