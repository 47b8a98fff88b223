// Compound curves: the chain of curves and the share of the concatenation's nodes each
// curve gets (compound_curve.h says what Gmsh 4.8.4 does and where we differ).
#include "mesh/compound_curve.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace sm {

std::vector<CompoundLink> chain_compound(const geo::Model& model, const std::vector<int>& curves) {
  std::set<int> seen;
  std::map<int, std::vector<int>> at;   // vertex -> positions in `curves` of the curves there
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const int tag = std::abs(curves[i]);
    const geo::ModelCurve* c = model.curve(tag);
    if (!c || !seen.insert(tag).second) return {};
    at[c->begin].push_back(static_cast<int>(i));
    at[c->end].push_back(static_cast<int>(i));
  }
  if (curves.empty()) return {};
  // A chain: no vertex with more than two curve ends, two free ends or none (closed).
  int free_ends = 0;
  int start = 0;
  int start_rank = static_cast<int>(curves.size());
  for (const auto& [v, ends] : at) {
    if (ends.size() > 2) return {};
    if (ends.size() == 1) {
      ++free_ends;
      if (ends[0] < start_rank) start = v, start_rank = ends[0];
    }
  }
  if (free_ends != 0 && free_ends != 2) return {};
  const geo::ModelCurve* first = model.curve(std::abs(curves[0]));
  if (free_ends == 0) start = first->begin;
  else if (start_rank == 0 && first->begin != first->end && at.at(first->begin).size() == 1)
    start = first->begin;   // a one-curve chain, or the first curve at the free end: its own direction
  std::vector<CompoundLink> chain;
  std::vector<char> used(curves.size(), 0);
  int v = start;
  // Each step uses one more curve: at most curves.size() steps.
  for (std::size_t step = 0; step < curves.size(); ++step) {
    int next = -1;
    for (int i : at.at(v))
      if (!used[static_cast<std::size_t>(i)]) {
        next = i;
        break;
      }
    if (next < 0) return {};   // not connected
    used[static_cast<std::size_t>(next)] = 1;
    const geo::ModelCurve* c = model.curve(std::abs(curves[static_cast<std::size_t>(next)]));
    const bool reversed = c->begin != v;
    chain.push_back({c->tag, reversed});
    v = reversed ? c->begin : c->end;
  }
  return chain;
}

std::vector<std::vector<double>> compound_node_positions(const std::vector<double>& totals, int min_segments) {
  std::vector<std::vector<double>> out(totals.size());
  double a = 0;
  std::vector<double> cum{0.0};   // the integral at each link's end
  for (double t : totals) cum.push_back(a += std::max(t, 0.0));
  if (!std::isfinite(a) || a <= 0) return out;
  const double count = std::max(static_cast<double>(min_segments) + 1, std::floor(a + 1.99));
  if (!(count <= 2147483647.0)) return out;   // beyond what a curve mesh holds (mesh1d.h's kMaxCurveNodes)
  const long long n = static_cast<long long>(count);
  const double step = a / static_cast<double>(n - 1);
  // The node nearest each inner end point moves onto it (not the chain's ends, not twice).
  std::set<long long> moved;
  for (std::size_t j = 1; j + 1 < cum.size(); ++j) {
    const long long k = std::llround(cum[j] / step);
    if (k >= 1 && k <= n - 2 && !moved.count(k)) moved.insert(k);
  }
  const double eps = 1e-9 * step;   // a node within this of an end point is that point
  for (std::size_t i = 0; i < totals.size(); ++i) {
    const long long lo = std::max(1LL, static_cast<long long>(std::floor(cum[i] / step)));
    const long long hi = std::min(n - 2, static_cast<long long>(std::ceil(cum[i + 1] / step)));
    for (long long k = lo; k <= hi; ++k) {
      const double pos = static_cast<double>(k) * step;
      if (moved.count(k) || pos <= cum[i] + eps || pos >= cum[i + 1] - eps) continue;
      out[i].push_back(pos - cum[i]);
    }
  }
  return out;
}

}  // namespace sm
