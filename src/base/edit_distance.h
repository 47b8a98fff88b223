// Levenshtein distance between two names: the "did you mean" suggestions of
// options, field kinds and options, commands and variables all use it.
#pragma once

#include <cstddef>
#include <string_view>

namespace sm {

enum class LetterCase { Sensitive, Insensitive };

/// Insertions, deletions and substitutions turning `a` into `b`. O(|a| |b|):
/// callers cap the lengths they compare when the names come from hostile input.
std::size_t edit_distance(std::string_view a, std::string_view b, LetterCase c = LetterCase::Sensitive);

}  // namespace sm
