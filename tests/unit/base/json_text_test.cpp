// JSON text: escapes, UTF-8 kept, invalid bytes replaced, numbers round-trip, no NaN.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "base/json_text.h"

TEST_CASE("json_text: strings escaped, valid UTF-8 kept, invalid bytes replaced") {
  CHECK(sm::base::json_string("a\"b\\c\n") == "\"a\\\"b\\\\c\\u000a\"");
  CHECK(sm::base::json_string("caf\xC3\xA9") == "\"caf\xC3\xA9\"");
  CHECK(sm::base::json_string("x\xFFy\xC3") == "\"x\\ufffdy\\ufffd\"");
}

TEST_CASE("json_text: numbers in their shortest round-trip form; null for non-finite") {
  CHECK(sm::base::json_number(0.1) == "0.1");
  CHECK(sm::base::json_number(30000) == "30000");
  CHECK(std::stod(sm::base::json_number(1.0 / 3)) == 1.0 / 3);
  CHECK(sm::base::json_number(std::numeric_limits<double>::quiet_NaN()) == "null");
  CHECK(sm::base::json_number(-std::numeric_limits<double>::infinity()) == "null");
}
