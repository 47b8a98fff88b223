// Grouping a statement's diagnostics by location (see diagnostic_groups.h).
#include "lang/diagnostic_groups.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace sm::lang {

namespace {

bool same_notes(const std::vector<DiagNote>& a, const std::vector<DiagNote>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].range.file != b[i].range.file || a[i].range.begin != b[i].range.begin ||
        a[i].range.end != b[i].range.end || a[i].message != b[i].message)
      return false;
  return true;
}

// Only located diagnostics group: what a group saves is the source line and caret
// repeated under each, and a diagnostic without a location has none.
bool same_group(const Diagnostic& a, const Diagnostic& b) {
  return a.range.valid() && a.range.file == b.range.file && a.range.begin == b.range.begin &&
         a.range.end == b.range.end && a.severity == b.severity && same_notes(a.notes, b.notes);
}

std::string_view plural(Severity s) {
  switch (s) {
    case Severity::Error: return "errors";
    case Severity::Warning: return "warnings";
    case Severity::Note: return "notes";
  }
  return "diagnostics";
}

// "lon -12.3457, lat 45.1235: width 1234 m" (what is known of it).
std::string place_and_figure(const Diagnostic& d) {
  std::string s;
  if (d.item.has_lonlat) s = fmt::format("lon {:.4f}, lat {:.4f}", d.item.lon, d.item.lat);
  if (!d.item.figure.empty()) s += (s.empty() ? "" : ": ") + d.item.figure;
  return s.empty() ? d.message : s;
}

// A sort of member (a kind, and the DiagItem::what within it) and who belongs to it. Kinds
// are told by their kebab name: the kinds of one kebab name are one message's shapes (a
// passage with or without its source record), one kind to the reader.
struct Sort {
  std::string_view kebab;
  std::string_view what;
  std::vector<const Diagnostic*> members;
};

std::string render_group(const Diagnostics& diags, const std::vector<const Diagnostic*>& group,
                         const GroupRenderOptions& options) {
  const Diagnostic& first = *group.front();
  // Sorts in the order of their first member; kinds likewise for the header's counts.
  std::vector<Sort> sorts;
  std::vector<std::pair<std::string_view, std::size_t>> kinds;
  for (const Diagnostic* d : group) {
    const std::string_view kebab = diag_info(d->kind).kebab;
    auto k = kinds.begin();
    while (k != kinds.end() && k->first != kebab) ++k;
    if (k == kinds.end()) kinds.emplace_back(kebab, 1);
    else ++k->second;
    auto s = sorts.begin();
    while (s != sorts.end() && (s->kebab != kebab || s->what != d->item.what)) ++s;
    if (s == sorts.end()) sorts.push_back({kebab, d->item.what, {d}});
    else s->members.push_back(d);
  }
  std::string counts;
  for (const auto& [kebab, n] : kinds) counts += fmt::format("{}{} [{}]", counts.empty() ? "" : ", ", n, kebab);
  Diagnostic header;
  header.severity = first.severity;
  header.range = first.range;
  header.notes = first.notes;
  header.message = fmt::format("{} {} from this statement: {}", group.size(), plural(first.severity), counts);
  std::string out = diags.render(header);

  std::size_t hidden = 0;
  for (const Sort& s : sorts) {
    const std::string_view kebab = s.kebab;
    if (s.what.empty()) {
      const std::size_t shown = options.list_all ? s.members.size() : std::min(s.members.size(), kGroupShownPlain);
      for (std::size_t i = 0; i < shown; ++i) out += fmt::format("  {} [{}]\n", s.members[i]->message, kebab);
      if (shown < s.members.size()) out += fmt::format("  ... and {} more [{}]\n", s.members.size() - shown, kebab);
      hidden += s.members.size() - shown;
      continue;
    }
    out += fmt::format("  {} x {} [{}]\n", s.members.size(), s.what, kebab);
    // Ranked sorts (every member with a rank) are cut to their largest, largest first.
    std::vector<const Diagnostic*> members = s.members;
    const bool ranked =
        std::all_of(members.begin(), members.end(), [](const Diagnostic* d) { return std::isfinite(d->item.rank); });
    if (ranked && !options.list_all)
      std::stable_sort(members.begin(), members.end(),
                       [](const Diagnostic* a, const Diagnostic* b) { return a->item.rank > b->item.rank; });
    const std::size_t per = ranked ? kGroupShownRanked : kGroupShownPerWhat;
    const std::size_t shown = options.list_all ? members.size() : std::min(members.size(), per);
    for (std::size_t i = 0; i < shown; ++i) out += "      " + place_and_figure(*members[i]) + "\n";
    if (shown < s.members.size()) out += fmt::format("      ... and {} more\n", s.members.size() - shown);
    hidden += s.members.size() - shown;
  }
  if (hidden > 0 && !options.how_to_see_all.empty())
    out += fmt::format("  ({} of {} not listed: {})\n", hidden, group.size(), options.how_to_see_all);
  return out;
}

}  // namespace

std::string render_grouped(const Diagnostics& diags, std::span<const Diagnostic> batch,
                           const GroupRenderOptions& options) {
  std::vector<std::vector<const Diagnostic*>> groups;
  for (const Diagnostic& d : batch) {
    auto g = groups.begin();
    while (g != groups.end() && !same_group(*g->front(), d)) ++g;
    if (g == groups.end()) groups.push_back({&d});
    else g->push_back(&d);
  }
  std::string out;
  for (const auto& g : groups) {
    if (!g.front()->range.valid()) out += options.unlocated_prefix;
    out += g.size() == 1 ? diags.render(*g.front()) : render_group(diags, g, options);
  }
  return out;
}

}  // namespace sm::lang
