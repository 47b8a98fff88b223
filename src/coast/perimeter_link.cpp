// See perimeter_link.h. Events are the chain ends on the perimeter sorted by t; the filled
// state of each side is constant between two consecutive events and toggles at an event
// of that side, which checks the orientations (a side must alternate open, close).
#include "coast/perimeter_link.h"

#include <algorithm>

namespace sm::coast {

PerimeterLink link_along_perimeter(const std::vector<PerimeterChain>& chains, bool inside_filled,
                                   bool outside_filled) {
  PerimeterLink out;
  const std::size_t n = chains.size();
  out.next.assign(n, static_cast<std::size_t>(-1));
  out.ccw.assign(n, 1);
  struct Event { double t; int kind; std::size_t chain; };   // kind 0: last point, 1: first point
  std::vector<Event> ev;
  for (std::size_t c = 0; c < n; ++c) {
    if (chains[c].t_last >= 0) ev.push_back({chains[c].t_last, 0, c});
    if (chains[c].t_first >= 0) ev.push_back({chains[c].t_first, 1, c});
  }
  if (ev.empty()) return out;
  std::sort(ev.begin(), ev.end(), [](const Event& a, const Event& b) {
    return a.t != b.t ? a.t < b.t : a.kind != b.kind ? a.kind < b.kind : a.chain < b.chain;
  });
  const std::size_t m = ev.size();
  // An event opens its side's filled part counter-clockwise after it: inside at a last
  // point, outside at a first point.
  auto opens = [&](const Event& e) { return chains[e.chain].outside == (e.kind == 1); };
  // filled[s][i]: side s (0 inside, 1 outside) in the interval after event i.
  std::vector<char> filled[2];
  std::size_t toggle_bad = n;   // a side opened (or closed) twice in a row, at this chain
  for (int s = 0; s < 2; ++s) {
    filled[s].assign(m, s == 0 ? inside_filled : outside_filled);
    std::size_t last = m;   // the side's last event: its state wraps round to the start
    for (std::size_t i = 0; i < m; ++i)
      if (static_cast<int>(chains[ev[i].chain].outside) == s) last = i;
    if (last == m) continue;
    bool state = opens(ev[last]);
    for (std::size_t i = 0; i < m; ++i) {
      if (static_cast<int>(chains[ev[i].chain].outside) == s) {
        const bool o = opens(ev[i]);
        if (o == state && toggle_bad == n) toggle_bad = ev[i].chain;
        state = o;
      }
      filled[s][i] = state;
    }
  }
  // Chains on one side only with the other empty (a region): every last point walks
  // counter-clockwise, and the check is that the next end is a first point.
  bool any_outside = false;
  for (const PerimeterChain& c : chains) any_outside |= c.outside;
  const bool one_side = !any_outside && !outside_filled;
  std::vector<std::size_t> pos_last(n, m);
  for (std::size_t i = 0; i < m; ++i)
    if (ev[i].kind == 0) pos_last[ev[i].chain] = i;
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t i = pos_last[c];
    if (i == m) continue;
    const std::size_t prev = (i + m - 1) % m;
    const bool fwd = one_side || (filled[0][i] && !filled[1][i]);         // inside filled after: walk ccw
    const bool back = !one_side && filled[1][prev] && !filled[0][prev];   // outside filled before: walk cw
    if (fwd == back) {
      out.error = fwd || toggle_bad != n ? PerimeterLinkError::Inconsistent : PerimeterLinkError::NoBoundary;
      out.bad_chain = c;
      return out;
    }
    const Event& to = ev[fwd ? (i + 1) % m : prev];
    if (to.kind != 1) {
      out.error = PerimeterLinkError::Inconsistent;
      out.bad_chain = c;
      return out;
    }
    out.next[c] = to.chain;
    out.ccw[c] = fwd ? 1 : 0;
  }
  if (toggle_bad != n) {
    out.error = PerimeterLinkError::Inconsistent;
    out.bad_chain = toggle_bad;
  }
  return out;
}

}  // namespace sm::coast
