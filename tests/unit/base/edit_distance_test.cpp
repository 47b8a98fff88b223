#include <doctest/doctest.h>

#include "base/edit_distance.h"

using namespace sm;

TEST_CASE("edit_distance: insertions, deletions, substitutions, letter case") {
  CHECK(edit_distance("", "") == 0);
  CHECK(edit_distance("Algorithm", "Algoritm") == 1);
  CHECK(edit_distance("kitten", "sitting") == 3);
  CHECK(edit_distance("", "abc") == 3);
  CHECK(edit_distance("Threshold", "threshold") == 1);
  CHECK(edit_distance("Threshold", "threshold", LetterCase::Insensitive) == 0);
  CHECK(edit_distance("abc", "xyz") == edit_distance("xyz", "abc"));
}
