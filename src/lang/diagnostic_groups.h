// A statement's diagnostics for the terminal: the many that share one location (a
// coastline import reports one per repaired place) shown as one group, with one caret,
// the counts per sort and a short list of places and figures, instead of a wall.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "lang/diagnostics.h"

namespace sm::lang {

/// How many of one sort (DiagItem::what) a cut group lists; the others are counted.
inline constexpr std::size_t kGroupShownPerWhat = 3;
/// How many of one sort a cut group lists when its members are ranked (DiagItem::rank):
/// the largest, largest first.
inline constexpr std::size_t kGroupShownRanked = 5;
/// How many diagnostics of one kind without a DiagItem::what a cut group lists.
inline constexpr std::size_t kGroupShownPlain = 5;

struct GroupRenderOptions {
  bool list_all = false;          ///< list every member of a group, nothing cut
  std::string_view how_to_see_all;  ///< the last line of a cut group ("-v 6 lists every one")
  std::string_view unlocated_prefix;  ///< put before a diagnostic without a location ("stereomesh: ")
};

/// The text of one statement's diagnostics (ends with '\n'): each set of diagnostics with
/// the same location, severity and notes becomes one group, in the order of its first
/// member; a group of one, and a diagnostic without a location, is rendered as
/// Diagnostics::render does (after options.unlocated_prefix when it has no location). A group of several has
/// one header (location, severity, how many of each kind), the source line with its
/// caret, the shared notes, then its members: those with a DiagItem::what counted per
/// sort with their places and figures, the others by their messages.
std::string render_grouped(const Diagnostics& diags, std::span<const Diagnostic> batch,
                           const GroupRenderOptions& options);

}  // namespace sm::lang
