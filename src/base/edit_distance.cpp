// One-row dynamic programme for the Levenshtein distance (see edit_distance.h).
#include "base/edit_distance.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace sm {

std::size_t edit_distance(std::string_view a, std::string_view b, LetterCase c) {
  auto same = [c](char x, char y) {
    if (c == LetterCase::Insensitive)
      return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    return x == y;
  };
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];  // row[i-1][j-1]
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace sm
